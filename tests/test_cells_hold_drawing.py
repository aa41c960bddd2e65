"""A notebook cell runs holding ``widgets.common.DRAWING`` (stop 45's CI: a cell read a
PlaneExplorer's values while a picture drawn ahead, on a subshell's thread, had set it to
another slider position)."""

import threading

import pytest

from teachraster.widgets import common

InteractiveShell = pytest.importorskip("IPython.core.interactiveshell").InteractiveShell


def _taken_elsewhere() -> bool:
    """Can another thread take DRAWING now (as a subshell drawing ahead would)?"""
    got = []

    def take():
        ok = common.DRAWING.acquire(timeout=0.2)
        got.append(ok)
        if ok:
            common.DRAWING.release()

    thread = threading.Thread(target=take)
    thread.start()
    thread.join()
    return got[0]


def test_another_thread_waits_while_a_cell_runs_and_not_after():
    shell = InteractiveShell.instance()
    try:
        common._cells_hold_drawing(shell)
        common._cells_hold_drawing(shell)  # registered once
        shell.user_ns["elsewhere"] = _taken_elsewhere
        result = shell.run_cell("during = elsewhere()")
        assert result.success
        assert shell.user_ns["during"] is False
        assert _taken_elsewhere() is True
        failed = shell.run_cell("1 / 0")  # a failing cell lets go too
        assert not failed.success
        assert _taken_elsewhere() is True
    finally:
        shell.events.unregister("pre_run_cell", common._hold_drawing)
        shell.events.unregister("post_run_cell", common._let_go_of_drawing)
        InteractiveShell.clear_instance()


def test_a_cell_that_registered_the_hooks_mid_way_lets_go_of_nothing():
    common._let_go_of_drawing(None)  # no pre_run_cell before it: no release error
    assert _taken_elsewhere() is True
