"""Exercises with a checker that explains every wrong answer by the rules.

>>> from teachraster import exercises as ex
>>> ex.names()[:8]
['edge_function', 'covers', 'fill', 'split_point', 'barycentric', 'perspective', 'depth_test', 'clip_near']
>>> report = ex.check("depth_test", lambda incoming, stored: incoming <= stored)
>>> report.passed
False
>>> print(report.failures[0].explanation)      # doctest: +ELLIPSIS
the incoming depth 0.5 equals the stored 0.5: it must fail; your function let it pass: a tie ...

How it is built (one engine for every exercise):

- :mod:`.exercise` says what an exercise is: its cases (the hard-case catalogue, then seeded
  random ones), how its answer is read (:mod:`.answers`: ``None`` is a missing ``return``,
  text is not a number), the rule in words with the case's numbers, and a table of typical
  mistakes, each a wrong solution the checker runs itself.
- :mod:`.value_checks` runs the cases, compares, and builds the :class:`Report`;
  :mod:`.diagnosis` names the mistake behind the failures: a constant answer first, then a
  mistake that gives every answer, then one that gives this answer; float32 only within its
  rounding (an answer within float32's rounding passes, and the report says float32). Every
  failure has a kind, and the summary shows one failure of each kind first.
- :mod:`.running`, :mod:`.alarm` and :mod:`.interrupt` bound the time: ``check(name, fn,
  budget=10.0)`` gives the student's code 10 s of CPU (a lecturer raises it for a class with
  ``TEACHRASTER_CHECK_BUDGET``), a case a fifth of it, and stop an endless loop whatever it
  catches; :mod:`.output` keeps what the function prints aside.
- :mod:`.package_answers` tells when the answer is the package's own function (it does not
  count); :mod:`.scenes` and :mod:`.picture_scenes` draw the student's function in a whole
  picture beside the package's (``report.compare(ax)``).
- ``capstone(scene, covers=...)`` renders a built-in scene with the student's own functions
  beside the package's (:mod:`.capstone_render`); ``broken_frame(n)`` is one of the frames
  lesson 11's exercises diagnose (:mod:`teachraster.exercises.broken_frames`),
  ``frames_to_inspect()`` every one of them and its intended frame for the ``FrameInspector``,
  ``frame_pairs()`` which two are a pair, ``frame_marks()`` the pixels each opens at.

The checker sits above the study layer: it takes its cases from the hard-case catalogue
(:mod:`teachraster.study.hardcases`) and its expected answers from the core, so there is one
top-left rule and one reference for every answer. matplotlib is imported only when a report
is drawn (:meth:`Report.plot`).
"""

from .broken_frames import (
    CAUSES,
    EVIDENCE,
    broken_frame,
    frame_marks,
    frame_note,
    frame_pairs,
    frames_to_inspect,
)
from .capstone_render import BUDGET as CAPSTONE_BUDGET
from .capstone_render import CALL_LIMIT as CAPSTONE_CALL_LIMIT
from .capstone_render import WALL_LIMIT as CAPSTONE_WALL_LIMIT
from .capstone_render import capstone
from .checks import check, names
from .report import Failure, Report

__all__ = [
    "CAPSTONE_BUDGET",
    "CAPSTONE_CALL_LIMIT",
    "CAPSTONE_WALL_LIMIT",
    "CAUSES",
    "EVIDENCE",
    "Failure",
    "Report",
    "broken_frame",
    "frame_note",
    "capstone",
    "check",
    "frame_marks",
    "frame_pairs",
    "frames_to_inspect",
    "names",
]

# r8 11-3: the submodule was one Tab away (``ex.broken_frames._answer(n)``); it stays importable
# by its full name, like any module, but is no attribute of ``ex``.
del broken_frames  # noqa: F821 - bound by the import of its names above
