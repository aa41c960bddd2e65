"""Review r122 (exercises 03, 08, 12 played as students in fresh processes): a correct
barycentric printing 200 lines a call was told "the check ran for 0.088 s of wall-clock time
... the machine is too busy" (D3-2), 3.2's and trilinear's checks gave the answer's words on a
first try (N3-2, N12-1), 8.2 called its bound "the nearest depth the triangle can have", and
the reference of 8.2 also clamped the plane to the farthest vertex (D8-6).
"""

from __future__ import annotations

from exercise_solutions import CORRECT

from teachraster import exercises as ex
from teachraster.exercises import output, running
from teachraster.exercises.alarm import Alarm


class Costly:
    """An argument whose formatting is counted (a big array's ``str`` costs CPU)."""

    formatted = 0

    def __str__(self):
        Costly.formatted += 1
        return "costly"


def test_printing_past_the_cap_formats_nothing_and_costs_no_cpu():
    """D3-2: formatting the prints of a chatty function ate the CPU budget (10.4 s of CPU for
    30 000 prints of arrays: "the check's budget ... ran out on case 140"). Past the lines kept,
    a print is counted, not formatted."""
    Costly.formatted = 0
    right = CORRECT["barycentric"]

    def chatty(xy, p):
        for k in range(200):
            print("debug", k, Costly())
        return right(xy, p)

    report = ex.check("barycentric", chatty, budget=60)
    assert report.passed, str(report)
    assert Costly.formatted <= output.KEEP, Costly.formatted
    assert "your function printed 30000 lines" in str(report), str(report)


def test_print_to_a_file_of_ones_own_is_not_swallowed(tmp_path):
    path = tmp_path / "log.txt"
    with output.captured() as out, open(path, "w") as fh:
        for k in range(output.KEEP + 5):
            print("x", k)
        print("kept", file=fh)
    assert path.read_text() == "kept\n"
    assert out.lines == output.KEEP + 5


def _stopped_on_the_wall(cap: float, seconds: float, check_wall: float) -> str:
    b = running.Budget(10.0)
    b.start -= check_wall
    b.used = 0.5
    alarm = Alarm(seconds, None, 5 * seconds, cap)
    alarm.why = "wall"
    alarm._end = (0.007, cap)  # frozen: CPU and wall seconds of the case
    return running._timeout(alarm, b, "120 of 150").error


def test_the_checks_wall_clock_limit_quotes_the_checks_time_not_the_cases():
    """D3-2: the case's share of what was left (0.088 s) was quoted as the check's time."""
    text = _stopped_on_the_wall(cap=0.088, seconds=2.0, check_wall=99.95)
    assert "0.088 s" not in text, text
    assert text.startswith("the check ran for 100 s of wall-clock time (its limit: 100 s"), text
    assert "your function computed for 0.51 s of it: the machine is too busy" in text, text


def test_a_cases_own_wall_clock_cap_is_quoted_as_the_cases():
    text = _stopped_on_the_wall(cap=40.0, seconds=2.0, check_wall=41.0)
    assert text.startswith("the case ran for 40 s of wall-clock time on case 120 of 150"), text
    assert "computed for 0.007 s of it" in text, text
