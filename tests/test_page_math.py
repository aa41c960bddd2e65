"""Formulas of the lesson pages rendered at export (``teachraster html``): MathML, no MathJax.

Every formula of every lesson and exercise is converted, and nothing of its TeX is left in
the MathML (a command the converter does not know would be left as ``\\name``)."""

from __future__ import annotations

from pathlib import Path

import nbformat
import pytest

pytest.importorskip("latex2mathml")
pytest.importorskip("nbconvert")

from teachraster.cli.page_math import (  # noqa: E402
    formulas,
    markdown_to_html,
    normalise_tex,
    tex_to_mathml,
    untranslated,
)

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb")) + sorted(
    (ROOT / "notebooks" / "exercises").glob("*.ipynb")
)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_formula_of_every_lesson_converts_to_mathml(path):
    nb = nbformat.read(path, as_version=4)
    found = [f for c in nb.cells if c.cell_type == "markdown" for f in formulas(c.source)]
    for tex, display in found:
        mathml = tex_to_mathml(tex, display=display)
        assert mathml.startswith("<math") and "merror" not in mathml, tex
        assert untranslated(mathml) is None, (tex, untranslated(mathml))


def test_lesson_01_has_its_formulas():
    nb = nbformat.read(ROOT / "notebooks" / "01_span_tables.ipynb", as_version=4)
    assert sum(len(formulas(c.source)) for c in nb.cells if c.cell_type == "markdown") >= 75


@pytest.mark.parametrize(
    ("tex", "text"),
    [
        (r"\text{max\_anisotropy}", "max_anisotropy"),  # lesson 09: an escape inside \text
        ("a,\\ \\\n\\Delta", "Δ"),  # lesson 01: a backslash ending a line is a space
    ],
)
def test_spellings_mathjax_reads_convert_too(tex, text):
    import html
    import re

    mathml = tex_to_mathml(tex)
    assert untranslated(mathml) is None
    assert text in html.unescape(re.sub(r"<[^>]+>", "", mathml))


def test_normalise_keeps_what_the_converter_reads():
    assert normalise_tex(r"\frac{a}{b} + \text{x}") == r"\frac{a}{b} + \text{x}"
    assert normalise_tex(r"\text{50\%}") == r"\text{50%}"


def test_markdown_gets_mathml_inline_and_displayed_and_keeps_dollars_in_code():
    out = markdown_to_html("Area $A = \\frac{1}{2}$ and\n\n$$E(p) > 0$$\n\n`$HOME` costs $5.")
    assert out.count("<math") == 2 and 'display="block"' in out
    assert "$HOME" in out and "\\frac" not in out


def test_a_formula_in_a_heading_stays_mathml():
    out = markdown_to_html("## 2. The split point $u_4$, from similar triangles")
    assert "<math" in out and "</math>" in out and "ns0" not in out
    assert 'id="2.-The-split-point-u4,-from-similar-triangles"' in out
