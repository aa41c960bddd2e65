"""Formulas rendered when a lesson is exported: MathML in the page, no MathJax, no network.

nbconvert leaves the TeX of a notebook's Markdown as it is (``$...$``) for MathJax, which its
page loads from a CDN: offline, every formula stays raw TeX. Here each formula is converted
once, at export, to MathML (``latex2mathml``, pure Python, from PyPI), which browsers render
natively (Chromium since version 109, Firefox and Safari for longer): the page needs no
script for its formulas. Every formula of every lesson converts (``tests/test_page_math.py``
checks them all).

Two spellings MathJax accepts and the converter does not are rewritten first: an escaped
character inside ``\\text{...}`` (``\\text{max\\_anisotropy}``) and a backslash at the end of
a line (TeX's control space, written ``\\`` then a newline).
"""

from __future__ import annotations

import html
import re

#: An escaped character MathJax reads as itself inside \text{...}.
_TEXT_ESCAPE = re.compile(r"\\([_%&#$])")
_TEXT = re.compile(r"\\(text|textrm|textit|textbf|mathrm)\{([^{}]*)\}")


def normalise_tex(tex: str) -> str:
    r"""TeX as ``latex2mathml`` reads it, meaning what MathJax makes of it.

    >>> normalise_tex(r"\text{max\_anisotropy} + a\
    ... b")
    '\\text{max_anisotropy} + a\\ b'
    """
    tex = re.sub(r"\\\n", r"\\ ", tex)  # a backslash then a newline: a control space
    return _TEXT.sub(_unescaped_text, tex)


def _unescaped_text(match) -> str:
    body = _TEXT_ESCAPE.sub(r"\1", match.group(2))
    return "\\" + match.group(1) + "{" + body + "}"


def tex_to_mathml(tex: str, *, display: bool = False) -> str:
    """One formula (without its ``$`` delimiters) as a ``<math>`` element.

    >>> tex_to_mathml("x^2")[-53:]
    '<mrow><msup><mi>x</mi><mn>2</mn></msup></mrow></math>'
    """
    from latex2mathml.converter import convert

    return convert(normalise_tex(tex), display="block" if display else "inline")


def markdown_renderer_class():
    """nbconvert's Markdown renderer with formulas turned into MathML (see the module)."""
    from nbconvert.filters.markdown_mistune import IPythonRenderer

    class MathMLRenderer(IPythonRenderer):
        def block_math(self, body: str) -> str:
            return tex_to_mathml(body, display=True)

        def inline_math(self, body: str) -> str:
            return tex_to_mathml(body)

        def latex_environment(self, name: str, body: str) -> str:
            return tex_to_mathml(f"\\begin{{{name}}}{body}\\end{{{name}}}", display=True)

        def heading(self, text: str, level: int, **attrs) -> str:
            return plain_mathml(super().heading(text, level, **attrs))

        def _html_embed_images(self, html: str) -> str:
            # nbconvert writes every HTML block again through BeautifulSoup to embed its
            # images, which closes the block's open tags: "<details><summary>...</summary>",
            # a block of its own above the Markdown it folds, came out as an empty fold with
            # that Markdown after it (review r249: the tour's reference tables). Only a block
            # with an image needs it.
            return super()._html_embed_images(html) if "<img" in html.lower() else html

    return MathMLRenderer


def plain_mathml(fragment: str) -> str:
    """MathML as HTML writes it: nbconvert's heading anchors go through ElementTree, which
    writes ``<ns0:math xmlns:ns0="...">``, a tag no browser renders as mathematics.

    >>> plain_mathml('<h2 xmlns:ns0="http://www.w3.org/1998/Math/MathML">'
    ...              '<ns0:math display="inline"><ns0:mi>u</ns0:mi></ns0:math></h2>')
    '<h2><math display="inline"><mi>u</mi></math></h2>'
    """
    match = re.search(r' xmlns:(\w+)="http://www.w3.org/1998/Math/MathML"', fragment)
    if match is None:
        return fragment
    prefix = match.group(1)
    fragment = fragment.replace(match.group(0), "")
    return re.sub(rf"<(/?){prefix}:", r"<\1", fragment)


def markdown_to_html(source: str, **renderer_options) -> str:
    """Markdown with formulas (nbconvert's parser) as HTML with MathML."""
    from nbconvert.filters.markdown_mistune import MarkdownWithMath

    renderer = markdown_renderer_class()(escape=False, **renderer_options)
    return MarkdownWithMath(renderer=renderer).render(source)


def formulas(source: str) -> list[tuple[str, bool]]:
    """Every formula of a Markdown text as nbconvert's parser finds it: (TeX, display)."""
    from nbconvert.filters.markdown_mistune import IPythonRenderer, MarkdownWithMath

    found: list[tuple[str, bool]] = []

    class Collector(IPythonRenderer):
        def block_math(self, body: str) -> str:
            found.append((body, True))
            return ""

        def inline_math(self, body: str) -> str:
            found.append((body, False))
            return ""

        def latex_environment(self, name: str, body: str) -> str:
            found.append((f"\\begin{{{name}}}{body}\\end{{{name}}}", True))
            return ""

    MarkdownWithMath(renderer=Collector(escape=False)).render(source)
    return found


def untranslated(mathml: str) -> str | None:
    """What the converter left as TeX in ``mathml`` (a backslash in its text), else None."""
    text = html.unescape(re.sub(r"<[^>]+>", "", mathml))
    match = re.search(r"\\[A-Za-z]+|\\.", text)
    return match.group(0) if match else None
