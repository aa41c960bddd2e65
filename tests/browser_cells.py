"""Typing a new cell into a notebook open in JupyterLab (Playwright), for the browser tests
that ask the kernel something after driving a widget."""

from __future__ import annotations


def run_new_cell(tab, source: str) -> int:
    """Add a code cell below the last one, put ``source`` into it and run it.

    Returns how many code cells there were before, so a caller can tell the new cell's output
    from older ones. Waits for the cell to exist before typing: a key typed before JupyterLab
    has made the cell goes to the previous one.
    """
    tab.locator(".jp-Notebook .jp-Cell").last.click()
    tab.keyboard.press("Escape")
    n = tab.locator(".jp-Notebook .jp-CodeCell").count()
    tab.keyboard.press("b")  # a new cell below
    tab.wait_for_function("n => document.querySelectorAll('.jp-Notebook .jp-CodeCell').length > n",
                          arg=n, timeout=10_000)  # fmt: skip
    tab.keyboard.press("Enter")
    # One input event for the whole source, as a paste gives, not a key per character: typed,
    # a 220-character line cost the page and Playwright 3.4 s of CPU, inserted 0.5 s
    # (measured 2026-12-06, five cells each way), and these cells only ask the kernel
    # something. Inserted text is not auto-indented either: the source arrives as written.
    tab.keyboard.insert_text(source)
    tab.keyboard.press("Shift+Enter")
    return n
