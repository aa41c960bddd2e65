"""Exercises with a checker that explains every wrong answer by the rules.

>>> from teachraster import exercises as ex
>>> ex.names()[:8]
['edge_function', 'covers', 'fill', 'split_point', 'barycentric', 'perspective', 'depth_test', 'clip_near']
>>> report = ex.check("depth_test", lambda incoming, stored: incoming <= stored)
>>> report.passed
False
>>> print(report.failures[0].explanation)      # doctest: +ELLIPSIS
the incoming depth 0.5 equals the stored 0.5: a tie keeps the fragment already stored ...

``check(name, fn, budget=10.0)`` never raises or hangs because of ``fn``: the whole check
takes about ``budget`` seconds at most, a case a fifth of it (an endless loop is reported after
2 s, whatever it catches), and its comparisons and explanations count against the budget too
(:mod:`.running`, :mod:`.interrupt`). Answers are read strictly (:mod:`.answers`): ``None`` is a
missing ``return``, text is not a number. ``report.compare(ax)`` shows the student's ``fill`` of
a whole scene beside the package's (:mod:`.compare`). ``capstone(scene, covers=...)``
renders a built-in scene with the student's own functions beside the package's
(:mod:`.capstone_render`); ``broken_frame(n)`` is one of the frames lesson 11's exercises diagnose
(:mod:`.broken_frames`).

The checker sits above the study layer: it takes its cases from the hard-case catalogue
(:mod:`teachraster.study.hardcases`) and its expected answers from the core, so there is one
top-left rule and one reference for every answer. matplotlib is imported only when a report
is drawn (:meth:`Report.plot`).
"""

from .broken_frames import CAUSES, broken_frame
from .capstone_render import capstone
from .checks import check, names
from .report import Failure, Report

__all__ = ["CAUSES", "Failure", "Report", "broken_frame", "capstone", "check", "names"]
