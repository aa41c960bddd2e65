"""The depth test exists once (the developers' brief: one place for each rule, every consumer
reads it): ``zbuffer.passes_depth_test`` decides it, with :func:`passed_on_arrival` and
:func:`resolve` built on it, and the depth stage, MSAA, the pixel history, Hi-Z and the
overlays call those. Here: its table (ties, NaN, +inf, ``depth_test=False``); the one-pass
resolve and the in-order test agree on every input; the history's decision and the frame's
agree on every sample of scenes with ties, z-fighting, depth masks and the test off; and no
module writes the compare again.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import numpy as np
import pytest
from test_render import clip_from_window

import teachraster as tr
from teachraster.pipeline.visibility.zbuffer import (
    last_written,
    passed_on_arrival,
    passes_depth_test,
    resolve,
    surely_in_front,
)

ROOT = Path(__file__).resolve().parents[1]


def test_the_compare_is_gl_less_and_off_is_gl_always():
    depth = np.array([0.25, 0.5, 0.75, np.nan, np.inf, -np.inf])
    assert passes_depth_test(depth, 0.5).tolist() == [True, False, False, False, False, True]
    assert passes_depth_test(depth, np.inf).tolist() == [True, True, True, False, False, True]
    assert passes_depth_test(depth, 0.5, depth_test=False).all()
    assert passes_depth_test(np.zeros((2, 3)), np.zeros(3), False).shape == (2, 3)
    # the bound holds whichever is drawn first, so equal ends are never sure
    assert surely_in_front([0.2, 0.5, 0.6, np.nan], 0.5).tolist() == [True, False, False, False]


@pytest.mark.parametrize("seed", range(12))
@pytest.mark.parametrize("depth_test", [True, False])
def test_one_pass_resolve_is_the_in_order_test(seed, depth_test):
    """resolve's minimum (ties: the earliest) is the last fragment passes_depth_test lets
    through in drawing order, also where depths tie, are NaN or +inf."""
    rng = np.random.default_rng(seed)
    m, n_pix = int(rng.integers(0, 60)), 9
    pixel = rng.integers(0, n_pix, m)
    depth = rng.choice([0.0, 0.25, 0.25, 0.5, 1.0, np.nan, np.inf], m)
    passed = passed_on_arrival(pixel, depth, None, depth_test)
    winner, tested = resolve(pixel, depth, n_pix, depth_test)
    shown, stored = last_written(pixel, passed, None, n_pix)
    np.testing.assert_array_equal(winner, shown)
    np.testing.assert_array_equal(winner, stored)
    assert tested == int((np.bincount(pixel, minlength=n_pix) > 1).sum())
    # the in-order test, one fragment at a time, as a GPU runs it
    buffer = np.full(n_pix, np.inf)
    for i in range(m):
        ok = passes_depth_test(depth[i], buffer[pixel[i]], depth_test)
        assert passed[i] == ok, (i, depth[i], buffer[pixel[i]])
        if ok:
            buffer[pixel[i]] = depth[i]


def _tie_scenes():
    """Scenes where the test decides on ties: duplicates, coplanar overlaps, z-fighting."""
    xy = np.array([[[1, 1], [22, 3], [4, 16]], [[2, 15], [23, 14], [12, 1]],
                   [[1, 1], [22, 3], [4, 16]], [[0, 8], [24, 6], [10, 17]]], float)  # fmt: skip
    ties = clip_from_window(xy, np.array([0.4, 0.4, 0.4, 0.6])[:, None].repeat(3, 1))
    tilt = np.array([[0.30, 0.31, 0.305], [0.3002, 0.3101, 0.3051], [0.30, 0.31, 0.305],
                     [0.2, 0.5, 0.3]])  # fmt: skip
    fight = clip_from_window(xy, tilt)
    return {"ties": (ties, {}), "zfight": (fight, {"depth_format": "unorm16"}),
            "masks": (fight, {"depth_write": [True, False, True, True]})}  # fmt: skip


def _history_decisions(frame, row, col):
    """{(triangle, sample): passed} of the records that reached the depth test."""
    h = frame.history(row, col)
    return {(r.triangle, r.sample): r.outcome == "passed" for r in h.records
            if r.outcome in ("passed", "failed_depth")}  # fmt: skip


def _frame_decisions(frame):
    """{(row, col): {(triangle, sample): passed}} from the frame's own trace."""
    t = frame.trace
    sample = np.zeros(len(t.fragment_row), np.int64) if t.fragment_sample is None else (
        t.fragment_sample)  # fmt: skip
    out: dict = {}
    for tri, row, col, s, ok in zip(t.fragment_triangle.tolist(), t.fragment_row.tolist(),
                                    t.fragment_col.tolist(), sample.tolist(),
                                    t.fragment_passed.tolist()):  # fmt: skip
        out.setdefault((row, col), {})[(tri, s)] = ok
    return out


@pytest.mark.parametrize("name", ["ties", "zfight", "masks"])
@pytest.mark.parametrize("depth_test", [True, False])
@pytest.mark.parametrize("samples", [1, 4])
def test_the_history_decides_every_sample_as_the_frame(name, depth_test, samples):
    """Every (triangle, sample) the frame tested has the same verdict in the pixel history
    (MSAA forced, so every pixel is tested sample by sample), and the trace's verdicts are
    passed_on_arrival's."""
    clip, kw = _tie_scenes()[name]
    force = "multisampling" if samples > 1 else None
    frame = tr.render(clip, 24, 18, samples=samples, depth_test=depth_test, trace=True,
                      force=force, **kw)  # fmt: skip
    t = frame.trace
    decided = _frame_decisions(frame)
    assert decided and any(not ok for d in decided.values() for ok in d.values()) == depth_test
    for (row, col), want in decided.items():
        assert _history_decisions(frame, row, col) == want, (row, col)
    # the trace's verdicts are the one in-order test's (one sample: Hi-Z's replay wrote them)
    slot = t.fragment_row * 24 + t.fragment_col
    if t.fragment_sample is not None:
        slot = slot * samples + t.fragment_sample
    writes = None if "depth_write" not in kw else np.asarray(kw["depth_write"])[
        t.fragment_triangle]  # fmt: skip
    expect = passed_on_arrival(slot, t.fragment_depth, writes, depth_test)
    np.testing.assert_array_equal(t.fragment_passed, expect)


@pytest.mark.parametrize("depth_test", [True, False])
def test_depth_test_off_shows_and_stores_the_last_fragment(depth_test):
    """GL_ALWAYS: without the test the last fragment drawn shows and leaves its depth, with
    MSAA decided whole or sample by sample alike."""
    clip, _ = _tie_scenes()["zfight"]
    plain = tr.render(clip, 24, 18, samples=4, depth_test=depth_test)
    forced = tr.render(clip, 24, 18, samples=4, depth_test=depth_test, force="multisampling")
    np.testing.assert_array_equal(plain.sample_triangle_id, forced.sample_triangle_id)
    np.testing.assert_array_equal(plain.sample_depth, forced.sample_depth)
    if not depth_test:
        one = tr.render(clip, 24, 18, depth_test=False, trace=True)
        t = one.trace
        last = np.full(24 * 18, -1)
        np.maximum.at(last, t.fragment_row * 24 + t.fragment_col, np.arange(len(t.fragment_row)))
        got = last.reshape(18, 24)
        np.testing.assert_array_equal(one.triangle_id, np.where(got >= 0, t.fragment_triangle[got],
                                                                -1))  # fmt: skip
        np.testing.assert_array_equal(one.depth, np.where(got >= 0, t.fragment_depth[got], np.nan))


# -- the compare is written once ---------------------------------------------------------------
#: An operand that names a depth or the buffer it is tested against.
DEPTH_NAMES = re.compile(r"depth|^(buffer|stored|incoming|ceiling|z_lo|z_hi|nearest|farthest)$")
#: The one place the compare is written.
HOME = "teachraster/pipeline/visibility/zbuffer.py"


def _name(node):
    while isinstance(node, (ast.Subscript, ast.Call)):
        node = node.value if isinstance(node, ast.Subscript) else node.func
    return node.id if isinstance(node, ast.Name) else getattr(node, "attr", None)


def depth_compares(path: Path) -> list[str]:
    """The ``<``, ``<=``, ``>``, ``>=`` between two non-constant operands one of which names
    a depth or a buffer, in one file: ``line: expression``."""
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if not isinstance(node, ast.Compare):
            continue
        if not any(isinstance(op, (ast.Lt, ast.LtE, ast.Gt, ast.GtE)) for op in node.ops):
            continue
        operands = [node.left, *node.comparators]
        if any(isinstance(o, ast.Constant) for o in operands):
            continue
        if any(DEPTH_NAMES.search(_name(o) or "") for o in operands):
            found.append(f"{node.lineno}: {ast.unparse(node)}")
    return found


def test_the_depth_compare_is_written_only_in_zbuffer():
    """No module but zbuffer.py compares a depth with a buffer itself: call passes_depth_test
    (or surely_in_front, passed_on_arrival, resolve). The exercises are left out: their
    tables of typical mistakes write wrong compares on purpose."""
    again = {}
    for path in sorted((ROOT / "teachraster").rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        if rel.startswith("teachraster/exercises/"):
            continue
        found = depth_compares(path)
        if rel == HOME:
            assert len(found) == 1 and "depth < buffer" in found[0], found
        elif found:
            again[rel] = found
    assert not again, f"the depth test written again (call zbuffer.passes_depth_test): {again}"


def test_the_scan_sees_the_compares_it_is_for(tmp_path):
    """The scan catches the forms the compare took before it had one place."""
    src = tmp_path / "m.py"
    src.write_text("a = r.depth < before\nb = z_lo[t] <= ceiling[c]\nc = nearest >= farthest\n"
                   "d = sorted_depth < before\ne = depth < 0.5\nf = count > 1\n")  # fmt: skip
    assert [f.split(":")[0] for f in depth_compares(src)] == ["1", "2", "3", "4"]


def test_the_depth_test_exercise_does_not_count_the_package_compare():
    import teachraster.exercises as ex

    assert ex.check("depth_test", lambda a, b: a < b).passed
    report = ex.check("depth_test", lambda a, b: bool(passes_depth_test(a, b)))
    assert not report.passed and "not counted" in str(report), str(report)
