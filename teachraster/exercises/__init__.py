"""Exercises with a checker that explains every wrong answer by the rules.

>>> from teachraster import exercises as ex
>>> ex.names()
['edge_function', 'covers', 'fill', 'split_point', 'barycentric', 'perspective', 'depth_test', 'clip_near', 'depth_to_unorm', 'coverage_fraction', 'resolve', 'mip_level', 'bilinear', 'trilinear', 'classify_block', 'line_pixels', 'over', 'over_premultiplied']
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
a whole scene beside the package's (:mod:`.compare`).

The checker sits above the study layer: it takes its cases from the hard-case catalogue
(:mod:`teachraster.study.hardcases`) and its expected answers from the core, so there is one
top-left rule and one reference for every answer. matplotlib is imported only when a report
is drawn (:meth:`Report.plot`).
"""

from .checks import check, names
from .report import Failure, Report

__all__ = ["Failure", "Report", "check", "names"]
