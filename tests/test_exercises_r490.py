"""r490: exercise 6.2 ``resolve_fragments`` and 6.3 ``covered_counts`` replace the
transcription tasks ``resolve`` and ``resolve_srgb`` (r482 T1; both still checked, for the
capstone's 12.9 and notebooks of earlier versions)."""

import json
from pathlib import Path

import numpy as np
import pytest
import r490_variants as v

from teachraster import exercises as ex
from teachraster import srgb_to_linear
from teachraster.exercises import resolve_codes as rc
from teachraster.exercises import resolve_fragments as rf
from teachraster.exercises import tries
from teachraster.pipeline.blending.colour_blending import srgb8_codes

ROOT = Path(__file__).resolve().parents[1]


def _fn(src, name):
    ns = {}
    exec(v.HEAD + src, ns)
    return ns[name]


def test_fragments_expected_match_package():
    for label, args, expected in rf.cases():
        assert np.allclose(rf.package_resolve(*args), expected, rtol=0, atol=1e-12), label


def test_codes_expected_match_package_and_stay_off_ties():
    for label, (code, fg, bg, s), expected in rc.cases():
        lf, lb = srgb_to_linear(fg / 255), srgb_to_linear(bg / 255)
        for k in range(s + 1):
            light = np.full(4, (k * lf + (s - k) * lb) / s)
            light[3] = 1.0
            assert srgb8_codes(light)[0] == rc.forward_code(k, fg, bg, s), label
            assert rc.tie_distance(k, fg, bg, s) > rc.TIE_MARGIN, label
        assert expected and code == rc.forward_code(expected[0], fg, bg, s), label


def test_cases_hold_the_subtle_ones():
    labels = [c[0] for c in rf.cases()]
    assert any("F = 0" in x for x in labels) and any("orphan" in x for x in labels)
    several = [c for c in rc.cases() if len(c[2]) > 1]
    assert len(several) >= 4  # fg = bg, a one-code gap and dark greys merged by 8 bits


@pytest.mark.parametrize(("name", "group"), [("resolve_fragments", "RF_RIGHT"),
                                             ("covered_counts", "CC_RIGHT")])  # fmt: skip
def test_correct_but_different_pass(name, group):
    for key, src in getattr(v, group).items():
        report = ex.check(name, _fn(src, name))
        assert report.passed, (key, str(report)[:400])


@pytest.mark.parametrize(("name", "group"), [("resolve_fragments", "RF_WRONG"),
                                             ("covered_counts", "CC_WRONG")])  # fmt: skip
def test_wrong_named_first(name, group):
    tries.spend_hints([name])
    for key, (src, words) in getattr(v, group).items():
        report = ex.check(name, _fn(src, name))
        assert not report.passed, key
        assert words in report.failures[0].explanation, (key, report.failures[0].explanation)


@pytest.mark.parametrize("name", ["resolve_fragments", "covered_counts"])
def test_stubs_told_as_such(name):
    said = []
    for src in v.STUBS[name]:
        report = ex.check(name, _fn(src, name))
        assert not report.passed
        said.append(str(report))
    assert "not implemented" in said[0]
    assert "every case" in said[1]
    assert ("unchanged" if name == "resolve_fragments" else "every k from 0 to S") in said[2]


def test_hints_hide_the_rule_until_two_answers_failed():
    tries.forget_hints("covered_counts")
    wrong = _fn(v.CC_WRONG["range_S"][0].replace("range(S)", "range(S, S + 1)"), "covered_counts")
    text = str(ex.check("covered_counts", wrong))
    assert "round(255 · encode" not in text


def test_notebook_asks_without_answering():
    nb = json.loads((ROOT / "notebooks/exercises/06_antialiasing.ipynb").read_text())
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in nb["cells"]]
    assert "resolve_fragments_check" in ids and "covered_counts_check" in ids
    assert "resolve_check" not in ids and "resolve_srgb_check" not in ids
    tasks = " ".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")
    assert "fragments[sample_fragment]" in tasks  # the question (c), never its answer
    for lesson in (ROOT / "notebooks").glob("*.ipynb"):
        text = lesson.read_text()
        assert "sample_fragment" not in text and "covered_counts" not in text, lesson.name


def test_the_checkers_own_models_and_the_packages_resolve_do_not_count():
    assert not ex.check("covered_counts", rc.expected_counts).passed
    assert not ex.check("resolve_fragments", rf.expected_fragments).passed
    report = ex.check("resolve_fragments", rf.package_resolve)
    assert not report.passed and "not counted" in str(report)
