"""``teachraster lessons`` and ``teachraster student-version`` (issue 10), in this checkout."""

from __future__ import annotations

import json

import pytest

from teachraster import course
from teachraster.cli import main


def test_the_course_is_found_in_the_checkout():
    here = sorted((course.notebooks_dir()).glob("*.ipynb"))
    assert [p.name for p in course.lessons()] == [p.name for p in here]
    assert course.lessons()[0].name.startswith("00_")
    assert course.exercises() and all(p.parent.name == "exercises" for p in course.exercises())


def test_lessons_copies_lessons_and_student_exercises(tmp_path, capsys):
    target = tmp_path / "course"
    assert main(["lessons", str(target)]) == 0
    out = capsys.readouterr().out
    assert f"jupyter lab {target}" in out and "00_tour.ipynb" in out
    assert [p.name for p in sorted(target.glob("*.ipynb"))] == [p.name for p in course.lessons()]
    for teacher in course.exercises():
        student = (target / "exercises" / teacher.name).read_text()
        assert "BEGIN SOLUTION" not in student and "raise NotImplementedError()" in student
        assert json.loads(student)["cells"]  # still a notebook


def test_lessons_never_overwrites_work_unless_forced(tmp_path, capsys):
    assert main(["lessons", str(tmp_path)]) == 0
    work = tmp_path / "exercises" / course.exercises()[0].name
    work.write_text("my work")
    with pytest.raises(SystemExit) as exc:
        main(["lessons", str(tmp_path)])
    assert exc.value.code == 2
    assert "already exists" in capsys.readouterr().err
    assert work.read_text() == "my work"
    assert main(["lessons", str(tmp_path), "--force"]) == 0
    assert work.read_text() != "my work"


def test_student_version_of_given_notebooks(tmp_path, capsys):
    src = course.exercises()[0]
    assert main(["student-version", str(src), "-o", str(tmp_path)]) == 0
    assert f"wrote {tmp_path / src.name}" in capsys.readouterr().out
    with pytest.raises(SystemExit):
        main(["student-version", str(tmp_path / "nope.ipynb"), "-o", str(tmp_path / "x")])
    assert "no such file" in capsys.readouterr().err


def test_student_version_keeps_the_markers_indentation():
    from teachraster.exercises.student_version import strip_solutions

    src = "x = 1\n    ### BEGIN SOLUTION\n    y = 2\n    ### END SOLUTION\nz = 3\n"
    assert strip_solutions(src) == (
        "x = 1\n    # YOUR CODE HERE\n    raise NotImplementedError()\nz = 3\n"
    )
