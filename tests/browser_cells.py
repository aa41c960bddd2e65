"""Typing a new cell into a notebook open in JupyterLab (Playwright), for the browser tests
that ask the kernel something after driving a widget."""

from __future__ import annotations


def run_new_cell(tab, source: str) -> int:
    """Add a code cell below the last one, type ``source`` into it and run it.

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
    tab.keyboard.type(source)
    tab.keyboard.press("Shift+Enter")
    return n
