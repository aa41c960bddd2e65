"""``teachraster html``: a lesson executed and written as one whole, self-contained page.

The notebook (a copy, in its own folder) runs in a kernel that first installs the offline
display of every widget (:func:`teachraster.widgets.offline.install`): each widget becomes an
HTML output that works without a kernel (players step and play, sliders move over pictures
drawn at export) or at least shows its picture, with metadata saying which. The page is
nbconvert's lab page with its formulas rendered to MathML at export
(:mod:`teachraster.cli.page_math`) and without the scripts it would load from a CDN
(require.js, MathJax, the widget manager): nothing is fetched when it is opened.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

#: Run in the kernel before the lesson's first cell (and removed from the page).
SETUP = "import teachraster.widgets.offline as _offline\n_offline.install()\ndel _offline"
#: Where nbconvert's template for the pages is.
TEMPLATE = Path(__file__).parent / "templates" / "offline_lesson.html.j2"
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
#: What an output that needs a widget manager shows instead (a widget not of this package).
NO_KERNEL = "<p><i>(a widget that needs a running kernel: run the notebook to use it)</i></p>"


@dataclass
class LessonPage:
    """What :func:`export_notebook_html` wrote: ``output``, the widgets by how the page shows
    them (``counts``: live, pictured, missing), and the formulas rendered as MathML."""

    output: Path
    counts: dict = field(default_factory=lambda: dict.fromkeys(("live", "pictured", "missing"), 0))
    formulas: int = 0

    def summary(self) -> str:
        """One line for the command's output."""
        c, n = self.counts, sum(self.counts.values())
        return (f"wrote {self.output}: {n} widget(s): {c['live']} live, {c['pictured']} "
                f"pictured, {c['missing']} missing; {self.formulas} formula(s) as MathML")  # fmt: skip


def export_notebook_html(notebook: Path, output: Path, *, timeout: int, quiet: bool = True
                         ) -> LessonPage:  # fmt: skip
    """Execute ``notebook`` (a copy, in its folder) and write it as one page (see the module)."""
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(notebook, as_version=4)
    nb.cells.insert(0, nbformat.v4.new_code_cell(SETUP))
    # read in the kernel: Predict shows its answer folded, FillPlayer its whole player
    os.environ["TEACHRASTER_STATIC_PAGES"] = "1"
    try:
        client = NotebookClient(nb, timeout=timeout, kernel_name="python3",
                                resources={"metadata": {"path": str(notebook.parent)}})  # fmt: skip
        client.execute()
    finally:
        os.environ.pop("TEACHRASTER_STATIC_PAGES", None)
    nb.cells.pop(0)
    for cell in nb.cells:  # the lesson's own numbering, as if the set-up had not run
        if cell.get("execution_count"):
            cell.execution_count -= 1
    page = LessonPage(output, formulas=count_formulas(nb))
    page.counts.update(count_widgets(nb))
    body = lesson_html(nb, notebook)
    output.write_text(body, encoding="utf-8")
    copy_linked_files(nb, output.parent)
    return page


def copy_linked_files(nb, folder: Path) -> list[Path]:
    """A copy of ``CONVENTIONS.md`` in ``folder`` if a Markdown cell of ``nb`` links it by its
    bare name, as it lies beside the lessons that ``teachraster lessons`` copies: the link
    then opens from the page too (review r249 S4: the tour's links to it). The copies made."""
    import shutil

    from .. import course

    text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
    name = course.CONVENTIONS
    if f"]({name})" not in text and f"]({name}#" not in text:
        return []
    source, target = course.conventions(), folder / name
    if not (target.exists() and target.samefile(source)):  # a page written beside it
        shutil.copyfile(source, target)
    return [target]


def lesson_html(nb, notebook: Path) -> str:
    """The executed notebook as the page's HTML (formulas as MathML, nothing fetched)."""
    from jinja2 import pass_context
    from nbconvert import HTMLExporter

    from .page_math import markdown_renderer_class

    class OfflineLessonExporter(HTMLExporter):
        @pass_context  # as nbconvert's own filter: jinja hands it the cell's context
        def markdown2html(self, context, source):
            from nbconvert.filters.markdown_mistune import MarkdownWithMath

            cell = context.get("cell", {})
            path = context.get("resources", {}).get("metadata", {}).get("path", "")
            renderer = markdown_renderer_class()(
                escape=False, attachments=cell.get("attachments", {}),
                embed_images=self.embed_images, path=path,
                anchor_link_text=self.anchor_link_text,
                exclude_anchor_links=self.exclude_anchor_links, **self.lexer_options,
            )  # fmt: skip
            return MarkdownWithMath(renderer=renderer).render(source)

    drop_hidden_inputs(nb)
    exporter = OfflineLessonExporter(template_file=str(TEMPLATE), embed_images=True)
    resources = {"metadata": {"name": notebook.stem, "path": str(notebook.parent)}}
    body, _ = exporter.from_notebook_node(nb, resources=resources)
    return body


#: A code cell tagged so (as Jupyter Book and nbconvert's TagRemovePreprocessor read it), or
#: collapsed in the notebook, shows only its outputs in the page.
HIDE_INPUT_TAG = "hide-input"


def drop_hidden_inputs(nb) -> int:
    """Leave out the source of the cells a student is not meant to read first; return how many.

    A ``Predict`` cell holds its answer: its input is collapsed in the notebook
    (``metadata.jupyter.source_hidden``, which JupyterLab and Notebook 7 honour) and tagged
    ``hide-input``. nbconvert's HTML templates read neither, only ``metadata.transient
    .remove_source`` (what its TagRemovePreprocessor sets): the page would print the answer
    above the question. Each such cell gets that flag, so only its outputs are shown.
    """
    dropped = 0
    for cell in nb.cells:
        meta = cell.get("metadata", {})
        hidden = meta.get("jupyter", {}).get("source_hidden", False)
        if cell.cell_type == "code" and (hidden or HIDE_INPUT_TAG in meta.get("tags", [])):
            meta["transient"] = {"remove_source": True}
            dropped += 1
    return dropped


def count_widgets(nb) -> dict:
    """The widgets of an executed lesson by how its page shows them, made ready for it.

    Outputs of this package's widgets carry ``{"teachraster": {"kind": ...}}`` in their
    metadata (:mod:`teachraster.widgets.offline`). A widget view without it (a widget of
    another package) cannot render without its kernel and the widget manager the page does
    not load: it is missing, shown by its own HTML if it has some, else by a note. The saved
    widget state goes too (nothing in the page reads it).
    """
    counts = dict.fromkeys(("live", "pictured", "missing"), 0)
    nb.metadata.pop("widgets", None)
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            kind = out.get("metadata", {}).get("teachraster", {}).get("kind")
            data = out.get("data", {})
            if kind in counts:
                counts[kind] += 1
            elif WIDGET_VIEW in data:
                counts["missing"] += 1
                data.setdefault("text/html", NO_KERNEL)
            data.pop(WIDGET_VIEW, None)
    return counts


def count_formulas(nb) -> int:
    """The formulas of the lesson's Markdown cells (each becomes MathML in the page)."""
    from .page_math import formulas

    return sum(len(formulas(c.source)) for c in nb.cells if c.cell_type == "markdown")
