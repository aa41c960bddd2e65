"""The interrupt's way out past the checker's own frames (stop 45's CI: exercise 3.1's
``call_barycentric``, whose ``except ValueError`` surrounds the student's call, was read as a
frame that may swallow the interrupt, so a loop catching everything was never stopped and the
pytest worker was killed after 900 s)."""

import ast
import pathlib
import sys

import numpy as np

from teachraster.exercises import interpolation, interrupt

PACKAGE = pathlib.Path(interrupt.__file__).resolve().parent.parent


def test_an_interrupt_raised_in_an_except_body_leaves_through_the_checkers_frames():
    seen = {}

    def student(xy, p):
        try:
            raise RuntimeError("an interrupt, caught")
        except BaseException:
            # raised here, a second interrupt would leave this frame: nothing of the
            # checker's between here and the guard may be counted as catching it
            seen["escapes"] = interrupt.escapes(sys._getframe(), seen["guard"])
        return np.array([1.0, 0.0, 0.0])

    def guard():
        seen["guard"] = sys._getframe()
        xy = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]])
        return interpolation.call_barycentric(student, (xy, np.array([1.0, 1.0])))

    guard()
    assert seen["escapes"] is True


def test_the_student_frame_inside_its_own_try_still_catches():
    seen = {}

    def student():
        try:
            seen["escapes"] = interrupt.escapes(sys._getframe(), seen["guard"])
        except BaseException:
            pass

    def guard():
        seen["guard"] = sys._getframe()
        student()

    guard()
    assert seen["escapes"] is False


def _catching_handlers(tree) -> bool:
    """Does the module have a handler that can catch a CaseInterrupt (a BaseException)?"""
    names = {"BaseException", "CaseInterrupt", "ThreadInterrupt"}
    for node in ast.walk(tree):
        if isinstance(node, ast.ExceptHandler):
            if node.type is None:
                return True
            types = node.type.elts if isinstance(node.type, ast.Tuple) else [node.type]
            for t in types:
                name = t.id if isinstance(t, ast.Name) else getattr(t, "attr", "")
                if name in names:
                    return True
    return False


def test_the_files_whose_handlers_can_catch_the_interrupt_are_the_listed_ones():
    found = {
        path.relative_to(PACKAGE).as_posix()
        for path in PACKAGE.rglob("*.py")
        if _catching_handlers(ast.parse(path.read_text(encoding="utf-8")))
    }
    assert found == set(interrupt.CATCHING_FILES)


def test_the_package_is_looked_through_and_a_students_code_is_not():
    assert interrupt.looked_through(interpolation.call_barycentric.__code__)
    assert not interrupt.looked_through(
        test_the_student_frame_inside_its_own_try_still_catches.__code__
    )
    running = sys.modules["teachraster.exercises.running"]
    assert not interrupt.looked_through(running._guarded.__code__)
