"""``teachraster lessons``, ``student-version`` and ``nbgrader`` (issues 10 and 17): the course
commands never lose a student's work, never leak an answer and never write where they should
not (symbolic links, outside DIR, onto their input, half a file on a full disk)."""

from __future__ import annotations

import errno
import json
import shlex
import sys
from datetime import datetime
from pathlib import Path

import pytest

from teachraster import course
from teachraster.cli import main
from teachraster.course import install as install_module
from teachraster.course.install import CourseError, install
from teachraster.exercises.student_version import (
    NotebookError,
    strip_solutions,
    student_notebook,
    student_text,
)

EXERCISES = course.exercises()


def _status(argv) -> int:
    try:
        return main([str(a) for a in argv])
    except SystemExit as exc:
        return exc.code


def _files(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in root.rglob("*") if p.is_file()}


def _nb(*cells) -> dict:
    return {"cells": list(cells), "metadata": {}, "nbformat": 4, "nbformat_minor": 5}


def _code(source: str, **nbgrader) -> dict:
    """A code cell; nbgrader flags as given, completed as nbgrader's metadata must be."""
    full = {
        "grade": False,
        "solution": False,
        "locked": False,
        "grade_id": "x",
        "schema_version": 3,
    }
    full.update(nbgrader)
    if full["grade"]:
        full.setdefault("points", 1)
    meta = {"nbgrader": full} if nbgrader else {}
    return {"cell_type": "code", "source": source, "metadata": meta, "outputs": [],
            "execution_count": None}  # fmt: skip


# -- where the course is -----------------------------------------------------------------------
def test_the_course_is_found_in_the_checkout():
    here = sorted((course.notebooks_dir()).glob("*.ipynb"))
    assert [p.name for p in course.lessons()] == [p.name for p in here]
    assert course.lessons()[0].name.startswith("00_")
    assert EXERCISES and all(p.parent.name == "exercises" for p in EXERCISES)
    assert course.conventions().read_text().startswith("# teachraster conventions")


# -- teachraster lessons -----------------------------------------------------------------------
def test_lessons_copies_lessons_student_exercises_and_conventions(tmp_path, capsys):
    target = tmp_path / "my course's lessons"  # a space and a quote: the command is quoted
    assert main(["lessons", str(target)]) == 0
    out = capsys.readouterr().out
    assert f"jupyter lab {shlex.quote(str(target))}" in out and "00_tour.ipynb" in out
    assert shlex.split(f"jupyter lab {shlex.quote(str(target))}")[2] == str(target)
    assert [p.name for p in sorted(target.glob("*.ipynb"))] == [p.name for p in course.lessons()]
    assert (target / "CONVENTIONS.md").read_bytes() == course.conventions().read_bytes()
    for teacher in EXERCISES:
        student = (target / "exercises" / teacher.name).read_text()
        assert "BEGIN SOLUTION" not in student and "raise NotImplementedError()" in student
        assert json.loads(student)["cells"]  # still a notebook
    assert not list(target.rglob(".*.tmp"))


def test_lessons_adds_what_is_missing_and_keeps_work_without_force(tmp_path, capsys):
    assert main(["lessons", str(tmp_path)]) == 0
    work = tmp_path / "exercises" / EXERCISES[0].name
    work.write_text("my work")
    deleted = tmp_path / course.lessons()[1].name
    deleted.unlink()
    (tmp_path / "CONVENTIONS.md").unlink()
    capsys.readouterr()
    assert main(["lessons", str(tmp_path)]) == 0  # nothing lost, so not an error
    out = capsys.readouterr().out
    assert deleted.is_file() and (tmp_path / "CONVENTIONS.md").is_file()
    assert work.read_text() == "my work"
    assert "kept 1 file" in out and f"exercises/{work.name}" in out and "--force" in out


def test_lessons_force_replaces_and_keeps_every_old_file(tmp_path, capsys, monkeypatch):
    assert main(["lessons", str(tmp_path)]) == 0
    work = tmp_path / "exercises" / EXERCISES[0].name
    shipped = work.read_bytes()
    work.write_text("my work")
    assert main(["lessons", str(tmp_path), "--force"]) == 0
    assert work.read_bytes() == shipped
    (backup,) = (tmp_path / "exercises").glob(f"{work.stem}.*{work.suffix}")
    assert backup.read_text() == "my work"
    assert backup.name[len(work.stem) + 1 : -len(work.suffix)].count("T") == 1  # a timestamp
    assert str(backup) in capsys.readouterr().out
    work.write_text("more work")  # again within the same minute: a second name, none lost
    assert main(["lessons", str(tmp_path), "--force"]) == 0
    backups = sorted((tmp_path / "exercises").glob(f"{work.stem}.*{work.suffix}"))
    assert sorted(b.read_text() for b in backups) == ["more work", "my work"]


def test_backup_names_never_reuse_a_name(tmp_path):
    now = datetime(2026, 11, 26, 10, 0)
    (tmp_path / "a.ipynb").write_text("1")
    for content in "234":
        install(tmp_path, {"a.ipynb": content.encode()}, force=True, now=now)
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == [
        "a.2026-11-26T10-00-2.ipynb",
        "a.2026-11-26T10-00-3.ipynb",
        "a.2026-11-26T10-00.ipynb",
        "a.ipynb",
    ]
    assert [(tmp_path / n).read_text() for n in names] == ["2", "3", "1", "4"]


def test_backups_are_copies_where_hard_links_fail(tmp_path, monkeypatch):
    def no_links(src, dst):
        raise PermissionError(1, "Operation not permitted")

    monkeypatch.setattr(install_module.os, "link", no_links)
    (tmp_path / "a.ipynb").write_text("old")
    (tmp_path / "a.2026-11-26T10-00.ipynb").write_text("older")
    now = datetime(2026, 11, 26, 10, 0)
    done = install(tmp_path, {"a.ipynb": b"new"}, force=True, now=now)
    assert done.replaced == [(tmp_path / "a.ipynb", tmp_path / "a.2026-11-26T10-00-2.ipynb")]
    assert (tmp_path / "a.2026-11-26T10-00.ipynb").read_text() == "older"
    assert (tmp_path / "a.2026-11-26T10-00-2.ipynb").read_text() == "old"
    assert (tmp_path / "a.ipynb").read_text() == "new"


@pytest.mark.parametrize("where", ["file", "dangling", "folder"])
@pytest.mark.parametrize("force", [False, True])
def test_lessons_never_writes_through_a_symlink(tmp_path, where, force, capsys):
    course_dir, outside = tmp_path / "course", tmp_path / "outside"
    outside.mkdir()
    (outside / "precious.txt").write_text("precious")
    (course_dir / "exercises").mkdir(parents=True)
    name = EXERCISES[0].name
    if where == "file":
        (course_dir / "exercises" / name).symlink_to(outside / "precious.txt")
    elif where == "dangling":
        (course_dir / "exercises" / name).symlink_to(outside / "new.ipynb")
    else:
        (course_dir / "exercises").rmdir()
        (course_dir / "exercises").symlink_to(outside, target_is_directory=True)
    before = _files(outside)
    assert _status(["lessons", course_dir, *(["--force"] if force else [])]) == 2
    assert "symbolic link" in capsys.readouterr().err
    assert _files(outside) == before  # nothing written outside DIR
    assert not list(course_dir.glob("*.ipynb"))  # and nothing at all: checked before writing


def test_names_that_would_leave_the_directory_are_refused(tmp_path):
    for name in ["../escape.ipynb", "/etc/x.ipynb", "a/../../b.ipynb", "", "."]:
        with pytest.raises(CourseError):
            install(tmp_path / "course", {name: b"x"})
    assert not (tmp_path / "escape.ipynb").exists()


def test_lessons_refuses_files_in_the_way(tmp_path, capsys):
    (tmp_path / "file").write_text("not a directory")
    assert _status(["lessons", tmp_path / "file"]) == 2
    (tmp_path / "c" / course.lessons()[0].name).mkdir(parents=True)  # a folder named like one
    assert _status(["lessons", tmp_path / "c"]) == 2
    assert "in the way" in capsys.readouterr().err


def _fail_halfway(monkeypatch):
    """Writes put half their bytes down, then fail as a full disk does."""
    real = open

    class Full:
        def __init__(self, f):
            self.f = f

        def write(self, data):
            self.f.write(data[: len(data) // 2])
            raise OSError(errno.ENOSPC, "No space left on device")

        def __getattr__(self, name):
            return getattr(self.f, name)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.f.close()

    monkeypatch.setattr(install_module, "open", lambda *a, **k: Full(real(*a, **k)), raising=False)


def test_a_full_disk_leaves_no_truncated_notebook(tmp_path, monkeypatch, capsys):
    assert main(["lessons", str(tmp_path)]) == 0
    work = tmp_path / "exercises" / EXERCISES[0].name
    work.write_text("my work")
    missing = tmp_path / course.lessons()[0].name
    missing.unlink()
    _fail_halfway(monkeypatch)
    assert _status(["lessons", tmp_path, "--force"]) == 1
    err = capsys.readouterr().err
    assert "No space left on device" in err and "Traceback" not in err
    assert not missing.exists()  # not half a notebook
    assert work.read_text() == "my work"  # the old file, whole
    assert not list(tmp_path.rglob(".*.tmp"))  # no temporary file left behind
    assert list(tmp_path.rglob(f"{work.stem}.*")) == [work]  # no backup: nothing replaced
    monkeypatch.undo()
    assert main(["lessons", str(tmp_path), "--force"]) == 0  # and a later run completes it
    assert missing.read_bytes() == course.lessons()[0].read_bytes()


def test_a_failed_replacement_keeps_the_old_file_and_makes_no_backup(tmp_path, monkeypatch):
    assert main(["lessons", str(tmp_path)]) == 0
    work = tmp_path / "exercises" / EXERCISES[-1].name
    work.write_text("my work")
    _fail_halfway(monkeypatch)
    assert _status(["lessons", tmp_path, "--force"]) == 1
    assert work.read_text() == "my work"
    assert list(tmp_path.rglob(f"{work.stem}*")) == [work]  # no backup, no temporary file


def test_lessons_refuses_to_write_onto_the_course_itself(capsys):
    assert _status(["lessons", course.notebooks_dir(), "--force"]) == 2
    assert "it would be written onto itself" in capsys.readouterr().err


# -- teachraster student-version ---------------------------------------------------------------
def test_student_version_of_given_notebooks(tmp_path, capsys):
    src = EXERCISES[0]
    assert main(["student-version", str(src), "-o", str(tmp_path)]) == 0
    assert f"wrote {tmp_path / src.name}" in capsys.readouterr().out
    with pytest.raises(SystemExit):
        main(["student-version", str(tmp_path / "nope.ipynb"), "-o", str(tmp_path / "x")])
    assert "no such file" in capsys.readouterr().err
    assert _status(["student-version", tmp_path, "-o", tmp_path / "y"]) == 2
    assert "is a directory" in capsys.readouterr().err


def test_student_version_keeps_the_markers_indentation():
    src = "x = 1\n    ### BEGIN SOLUTION\n    y = 2\n    ### END SOLUTION\nz = 3\n"
    assert strip_solutions(src) == (
        "x = 1\n    # YOUR CODE HERE\n    raise NotImplementedError()\nz = 3\n"
    )


MALFORMED = {
    "second BEGIN": "### BEGIN SOLUTION\na = 1\n### BEGIN SOLUTION\nb = 2\n### END SOLUTION",
    "END before BEGIN": "### END SOLUTION\na = 1\n### BEGIN SOLUTION\nb = 2\n### END SOLUTION",
    "BEGIN without END": "def f():\n    ### BEGIN SOLUTION\n    return 1",
    "END alone": "a = 1\n### END SOLUTION",
    "code before": "a = 1  ### BEGIN SOLUTION\nb = 2\n### END SOLUTION",
    "text after": "### BEGIN SOLUTION here\nb = 2\n### END SOLUTION",
    "lower case": "### begin solution\nb = 2\n### end solution",
    "underscore": "### BEGIN_SOLUTION\nb = 2\n### END_SOLUTION",
    "end inside": "### BEGIN SOLUTION\nb = 2  # END SOLUTION\n### END SOLUTION",
    "hidden tests unpaired": "assert f()\n### BEGIN HIDDEN TESTS\nassert g()",
    "mixed regions": "### BEGIN SOLUTION\nb = 2\n### END HIDDEN TESTS",
}


@pytest.mark.parametrize("kind", MALFORMED)
def test_student_version_refuses_malformed_markers_and_writes_nothing(tmp_path, kind, capsys):
    good = tmp_path / "a_good.ipynb"
    good.write_text(json.dumps(_nb(_code("### BEGIN SOLUTION\nx = 1\n### END SOLUTION"))))
    bad = tmp_path / "b_bad.ipynb"
    cells = [_code("import numpy"), _code(MALFORMED[kind], solution=True, grade=True)]
    bad.write_text(json.dumps(_nb(*cells)))
    out = tmp_path / "out"
    assert _status(["student-version", good, bad, "-o", out]) == 2
    err = capsys.readouterr().err
    assert f"{bad}: cell 1 (x), line " in err and "Traceback" not in err
    assert not out.exists()  # nothing written, not even the good notebook


def test_words_that_only_contain_a_marker_are_text():
    prose = "Send solutions by Friday; the legend: solution in blue.\nfriend solution"
    assert strip_solutions(prose) == prose
    for near_miss in [
        "# Begin Solution",
        "### END  SOLUTION",
        "#BEGIN-SOLUTION",
        "# end solutions",
    ]:
        with pytest.raises(NotebookError, match="stand alone"):
            strip_solutions(near_miss)


def test_marker_errors_name_the_line():
    source = "a = 1\nb = 2\n### END SOLUTION"
    with pytest.raises(NotebookError, match=r"nb: cell 0, line 3: END SOLUTION without"):
        student_notebook(_nb(_code(source)), "nb")


def test_student_version_clears_as_nbgrader_does():
    nb = _nb(
        _code("def f():\n    return 42", solution=True, grade_id="f"),  # no markers: all solution
        {
            "cell_type": "markdown",
            "metadata": {},
            "source": "Why?\n### BEGIN SOLUTION\nBecause.\n### END SOLUTION",
        },  # fmt: skip
        _code(
            "assert f() == 42\n### BEGIN HIDDEN TESTS\nassert f() > 0\n### END HIDDEN TESTS",
            grade=True,
            locked=True,
            points=1,
        ),  # fmt: skip
        _code("print(1)\n=== BEGIN MARK SCHEME ===\nworth it\n=== END MARK SCHEME ==="),
    )
    out = [c["source"] for c in student_notebook(nb)["cells"]]
    assert out == [
        "# YOUR CODE HERE\nraise NotImplementedError()",
        "Why?\nYOUR ANSWER HERE",
        "assert f() == 42",
        "print(1)",
    ]
    locked = student_notebook(nb)["cells"][2]["metadata"]
    assert locked["editable"] is False and locked["deletable"] is False
    with pytest.raises(NotebookError, match="'solution': true"):  # nbgrader refuses it too
        student_notebook(_nb(_code("### BEGIN SOLUTION\nx\n### END SOLUTION", solution=False)))


def test_student_version_of_a_student_version_is_itself(tmp_path):
    for path in EXERCISES:
        once = tmp_path / path.name
        once.write_text(student_text(path))
        assert student_text(once) == once.read_text()


@pytest.mark.parametrize(
    "content",
    ['{"a": 1}', "[]", '"text"', "{not json", '{"cells": 3}', '{"cells": [1]}',
     '{"cells": [], "nbformat": 3}', '{"cells": [{"cell_type": "code", "source": 5}]}'],
)  # fmt: skip
def test_student_version_reports_json_that_is_not_a_notebook(tmp_path, content, capsys):
    path = tmp_path / "in.ipynb"
    path.write_text(content)
    assert _status(["student-version", path, "-o", tmp_path / "out"]) == 2
    err = capsys.readouterr().err
    assert str(path) in err and "Traceback" not in err and "not" in err
    assert not (tmp_path / "out").exists()


def test_student_version_reports_a_binary_file(tmp_path, capsys):
    path = tmp_path / "in.ipynb"
    path.write_bytes(b"\x89PNG\r\n\x1a\n\xff\xfe")
    assert _status(["student-version", path, "-o", tmp_path / "out"]) == 2
    assert "not a Jupyter notebook" in capsys.readouterr().err


def test_student_version_never_writes_onto_its_input(tmp_path, capsys):
    src = tmp_path / EXERCISES[0].name
    src.write_bytes(EXERCISES[0].read_bytes())
    for extra in ([], ["--force"]):
        assert _status(["student-version", src, "-o", tmp_path, *extra]) == 2
        assert "onto itself" in capsys.readouterr().err
    assert src.read_bytes() == EXERCISES[0].read_bytes()
    link = tmp_path / "other"
    link.symlink_to(tmp_path, target_is_directory=True)  # the same folder by another name
    assert _status(["student-version", src, "-o", link, "--force"]) == 2
    assert src.read_bytes() == EXERCISES[0].read_bytes()


def test_student_version_refuses_two_inputs_with_one_output_name(tmp_path, capsys):
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "ex.ipynb").write_bytes(EXERCISES[0].read_bytes())
    args = [tmp_path / "a" / "ex.ipynb", tmp_path / "b" / "ex.ipynb", "-o", tmp_path / "out"]
    assert _status(["student-version", *args]) == 2
    assert "both be written as ex.ipynb" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_student_version_keeps_existing_outputs_unless_forced(tmp_path, capsys):
    src = EXERCISES[0]
    assert main(["student-version", str(src), "-o", str(tmp_path)]) == 0
    assert main(["student-version", str(src), "-o", str(tmp_path)]) == 0  # same: nothing lost
    (tmp_path / src.name).write_text("edited")
    assert _status(["student-version", src, "-o", tmp_path]) == 2
    assert "already exists" in capsys.readouterr().err
    assert (tmp_path / src.name).read_text() == "edited"
    assert main(["student-version", str(src), "-o", str(tmp_path), "--force"]) == 0
    assert [p.read_text() for p in tmp_path.glob(f"{src.stem}.*.ipynb")] == ["edited"]


# -- no answer leaks -----------------------------------------------------------------------------
def _answers(nb: dict) -> list[frozenset[str]]:
    """Each solution region's substantial lines, without spaces (`return out` may be anyone's)."""
    regions = []
    for cell in nb["cells"]:
        for line in "".join(cell["source"]).split("\n"):
            if "BEGIN SOLUTION" in line:
                regions.append(set())
            elif "END SOLUTION" in line:
                regions[-1] = frozenset(regions[-1])
            elif isinstance(regions[-1:] and regions[-1], set) and not line.strip().startswith("#"):
                if len("".join(line.split())) >= 16:
                    regions[-1].add("".join(line.split()))
    return [r for r in regions if r]


def test_no_student_notebook_holds_an_answer():
    """No student notebook holds any exercise's answer (its own or another's), e.g. the
    edge function of exercise 1 given in full in exercise 3: no solution region has all its
    substantial lines in a student notebook."""
    answers = [a for p in EXERCISES for a in _answers(json.loads(p.read_text()))]
    assert len(answers) >= len(EXERCISES)
    for path in EXERCISES:
        student = json.loads(student_text(path))
        text = {"".join(line.split()) for c in student["cells"] for line in
                "".join(c["source"]).split("\n")}  # fmt: skip
        assert not [a for a in answers if a <= text], path.name


# -- teachraster nbgrader ----------------------------------------------------------------------
def test_nbgrader_lays_out_a_course_without_needing_nbgrader(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "nbgrader", None)  # `import nbgrader` fails
    root = tmp_path / "course"
    assert main(["nbgrader", str(root)]) == 0
    for path in EXERCISES:
        assert (root / "source" / path.stem / path.name).read_bytes() == path.read_bytes()
        assert (root / "source" / path.stem / "CONVENTIONS.md").is_file()
    config = (root / "nbgrader_config.py").read_text()
    compile(config, "nbgrader_config.py", "exec")
    assert "c.CourseDirectory.course_id" in config
    assert f"cd {shlex.quote(str(root))}" in capsys.readouterr().out
    # again: nothing changes; an edited source is kept, and with --force backed up outside
    # source/ (so that nbgrader never releases an old teacher version)
    assert main(["nbgrader", str(root)]) == 0
    edited = root / "source" / EXERCISES[0].stem / EXERCISES[0].name
    edited.write_text("edited")
    assert main(["nbgrader", str(root)]) == 0 and edited.read_text() == "edited"
    assert main(["nbgrader", str(root), "--force"]) == 0
    assert edited.read_bytes() == EXERCISES[0].read_bytes()
    (backup,) = (root / "backups").rglob("*.ipynb")
    assert backup.read_text() == "edited"
    assert not [p for p in (root / "source").rglob("*.ipynb") if p.name.count(".") > 1]


def test_nbgrader_refuses_student_versions_and_malformed_markers(tmp_path, capsys):
    student = tmp_path / EXERCISES[0].name
    student.write_text(student_text(EXERCISES[0]))
    assert _status(["nbgrader", tmp_path / "c", student]) == 2
    assert "student version" in capsys.readouterr().err
    bad = tmp_path / "bad.ipynb"
    bad.write_text(json.dumps(_nb(_code("### BEGIN SOLUTION\nx = 1"))))
    assert _status(["nbgrader", tmp_path / "c", bad]) == 2
    assert "line 2: BEGIN SOLUTION without an END" in capsys.readouterr().err
    other = tmp_path / "ex.json"
    other.write_bytes(EXERCISES[0].read_bytes())
    assert _status(["nbgrader", tmp_path / "c", other]) == 2
    assert "*.ipynb" in capsys.readouterr().err
    assert not (tmp_path / "c").exists()


def test_a_misspelt_but_consistent_marker_pair_is_an_error_never_a_leak(tmp_path, capsys):
    for spelling in ("SOLUTON", "SOLUTIONS", "SOLUTION_"):
        src = f"def f():\n    ### BEGIN {spelling}\n    return 42\n    ### END {spelling}\n"
        with pytest.raises(NotebookError, match="spelt '### BEGIN SOLUTION'"):
            student_notebook(_nb(_code(src, solution=True)))
    src = "x = 1\n### BEGN SOLUTION\nsecret = 42\n### ED SOLUTION\n"
    with pytest.raises(NotebookError, match="line 2"):
        student_notebook(_nb(_code(src, solution=True)))
    # comments that merely mention the words stay comments
    fine = "# end of solution loop\n# begin drawing\n### BEGIN SOLUTION\nx = 1\n### END SOLUTION"
    student_notebook(_nb(_code(fine, solution=True)))


@pytest.mark.parametrize(
    "meta, words",
    [
        (
            {
                "grade": True,
                "solution": False,
                "locked": True,
                "schema_version": 3,
                "grade_id": "c",
            },
            "without points",
        ),  # fmt: skip
        (
            {"grade": False, "solution": True, "locked": False, "schema_version": 3},
            "without a grade_id",
        ),  # fmt: skip
        (
            {
                "grade": False,
                "solution": True,
                "locked": False,
                "schema_version": 3,
                "grade_id": "",
            },
            "without a grade_id",
        ),  # fmt: skip
        (
            {"grade": False, "solution": True, "schema_version": 3, "grade_id": "a"},
            "without locked",
        ),
        (
            {
                "grade": False,
                "solution": True,
                "locked": False,
                "schema_version": 1,
                "grade_id": "a",
            },
            "schema version 1",
        ),  # fmt: skip
        (
            {
                "grade": False,
                "solution": False,
                "locked": True,
                "task": True,
                "schema_version": 3,
                "grade_id": "t",
            },
            "must be markdown",
        ),  # fmt: skip
    ],
)
def test_student_version_refuses_what_nbgrader_refuses(meta, words):
    cell = {"cell_type": "code", "source": "x = 1", "metadata": {"nbgrader": meta},
            "outputs": [], "execution_count": None}  # fmt: skip
    with pytest.raises(NotebookError, match=words):
        student_notebook(_nb(cell))


def test_student_version_refuses_a_duplicate_grade_id_and_a_half_graded_markdown_cell():
    with pytest.raises(NotebookError, match="duplicate grade id"):
        student_notebook(_nb(_code("x = 1", locked=True), _code("y = 2", locked=True)))
    md = {"cell_type": "markdown", "source": "Why?", "metadata": {"nbgrader": {
        "grade": True, "solution": False, "locked": False, "points": 1, "grade_id": "why",
        "schema_version": 3}}}  # fmt: skip
    with pytest.raises(NotebookError, match="both a grade and a solution"):
        student_notebook(_nb(md))


def test_the_attachments_of_solution_cells_are_stripped():
    answer = {"image.png": {"image/png": "iVBORw0KGgo="}}
    md = {"cell_type": "markdown", "source": "Why?\n### BEGIN SOLUTION\n![](attachment:image.png)\n"
          "### END SOLUTION", "metadata": {"nbgrader": {
              "grade": True, "solution": True, "locked": False, "points": 1, "grade_id": "why",
              "schema_version": 3}}, "attachments": answer}  # fmt: skip
    task = {"cell_type": "markdown", "source": "![](attachment:figure.png)", "metadata": {},
            "attachments": {"figure.png": {"image/png": "iVBORw0KGgo="}}}  # fmt: skip
    cells = student_notebook(_nb(md, task))["cells"]
    assert "attachments" not in cells[0] and "attachment:" not in cells[0]["source"]
    assert cells[1]["attachments"]  # a figure of the question stays


# -- an upgrade: what the student never edited is refreshed ------------------------------------
def _as_an_older_version_shipped_it(root: Path, name: str) -> dict:
    """Make ``name`` hold what an earlier version shipped (other wording), and record that in
    the manifest as that version would have."""
    from teachraster.course import manifest

    path = root / name
    nb = json.loads(path.read_text(encoding="utf-8"))
    markdown = next(c for c in nb["cells"] if c["cell_type"] == "markdown")
    markdown["source"] = "".join(markdown["source"]) + "\n\n(the wording of an older version)"
    data = (json.dumps(nb, indent=1, ensure_ascii=False) + "\n").encode()
    path.write_bytes(data)
    recorded = manifest.read(root)
    recorded[name] = manifest.fingerprint(name, data)
    (root / manifest.NAME).write_bytes(manifest.text(recorded, "0.0.old"))
    return nb


def test_an_upgrade_refreshes_the_notebooks_the_student_never_edited(tmp_path, capsys):
    root = tmp_path / "course"
    main(["lessons", str(root)])
    lesson = sorted(p.name for p in root.glob("*.ipynb"))[0]
    exercise = "exercises/" + EXERCISES[0].name
    other = "exercises/" + EXERCISES[1].name
    new = {n: (root / n).read_bytes() for n in (lesson, exercise, other)}
    # the older version's lesson, run by the student (outputs: not an edit)
    nb = _as_an_older_version_shipped_it(root, lesson)
    code = next(c for c in nb["cells"] if c["cell_type"] == "code")
    code["outputs"] = [{"output_type": "stream", "name": "stdout", "text": "ran\n"}]
    code["execution_count"] = 1
    (root / lesson).write_text(json.dumps(nb, indent=1), encoding="utf-8")
    # the older version's exercise, left as it was; another exercise the student worked in
    _as_an_older_version_shipped_it(root, exercise)
    nb = _as_an_older_version_shipped_it(root, other)
    solution = next(c for c in nb["cells"] if c["metadata"].get("nbgrader", {}).get("solution"))
    solution["source"] = "def covers(xy, p):\n    return True  # my work"
    (root / other).write_text(json.dumps(nb, indent=1), encoding="utf-8")
    capsys.readouterr()
    main(["lessons", str(root)])
    said = capsys.readouterr().out
    assert (root / lesson).read_bytes() == new[lesson]
    assert (root / exercise).read_bytes() == new[exercise]
    assert "my work" in (root / other).read_text(encoding="utf-8")  # kept
    assert "refreshed 2 file(s) you had not edited" in said and "kept 1 file(s)" in said
    assert not list(root.rglob("*.20*.ipynb"))  # refreshing an untouched notebook keeps no copy
    # the kept exercise still counts as the older version's: an edit is never refreshed away
    main(["lessons", str(root)])
    assert "my work" in (root / other).read_text(encoding="utf-8")


def test_without_a_manifest_every_notebook_that_differs_is_kept(tmp_path, capsys):
    from teachraster.course import manifest

    root = tmp_path / "course"
    main(["lessons", str(root)])
    (root / manifest.NAME).unlink()  # a course copied by an older version
    lesson = sorted(root.glob("*.ipynb"))[0]
    lesson.write_text(lesson.read_text(encoding="utf-8").replace("#", "##", 1), encoding="utf-8")
    capsys.readouterr()
    main(["lessons", str(root)])
    assert "kept 1 file(s)" in capsys.readouterr().out


def test_the_printed_nbgrader_commands_quote_names(tmp_path, capsys):
    odd = tmp_path / "my ex's" / "01 the coverage.ipynb"
    odd.parent.mkdir()
    odd.write_bytes(EXERCISES[0].read_bytes())
    root = tmp_path / "a class; rm -rf"
    assert main(["nbgrader", str(root), str(odd)]) == 0
    out = capsys.readouterr().out
    assert f"nbgrader generate_assignment {shlex.quote('01 the coverage')}" in out
    assert f"teachraster nbgrader {shlex.quote(str(root))} --check-submissions" in out
    for line in out.splitlines():
        if line.startswith("    ") and "#" not in line.split("nbgrader", 1)[0]:
            shlex.split(line.split("#")[0])  # every command line parses as the shell would


def test_check_submissions_lists_what_nbgrader_would_score_0_silently(tmp_path, capsys):
    root = tmp_path / "class"
    assert main(["nbgrader", str(root), str(EXERCISES[0])]) == 0
    name, stem = EXERCISES[0].name, EXERCISES[0].stem
    release = json.loads(student_text(EXERCISES[0]))
    graded = [c for c in release["cells"] if c["metadata"].get("nbgrader", {}).get("grade")]

    def submit(student: str, nb: dict | None):
        folder = root / "submitted" / student / stem
        folder.mkdir(parents=True)
        if nb is not None:
            (folder / name).write_text(json.dumps(nb), encoding="utf-8")

    submit("ada", release)  # as released: fine
    stripped = json.loads(json.dumps(release))
    for cell in stripped["cells"]:
        cell["metadata"] = {}  # an editor that drops cell metadata
    submit("bob", stripped)
    deleted = json.loads(json.dumps(release))
    deleted["cells"].remove(next(c for c in deleted["cells"] if c["metadata"].get("nbgrader", {}).get("grade")))  # fmt: skip
    submit("cy", deleted)
    submit("dee", None)  # an empty folder
    capsys.readouterr()
    assert main(["nbgrader", str(root), "--check-submissions"]) == 1
    out = capsys.readouterr().out
    assert "submitted/ada/" not in out
    assert out.count("submitted/bob/") >= len(graded) and "metadata stripped" in out
    assert out.count("submitted/cy/") == 1 and "check cell" in out
    assert f"submitted/dee/{stem}/{name}: missing" in out
    assert "scores it 0 without a word" in out
    assert not (root / "source" / stem / "x").exists()  # it wrote nothing
    (root / "submitted").rename(tmp_path / "elsewhere")
    assert main(["nbgrader", str(root), "--check-submissions"]) == 0


def test_check_submissions_flags_a_cell_that_changes_the_checker(tmp_path, capsys):
    """r14 09-3: ``Report.assert_passed = lambda self: None`` in a solution cell made every
    later check pass under nbgrader whatever the answer, unflagged. --check-submissions now
    names such a cell (by its written code); an honest solution is not flagged."""
    root = tmp_path / "class"
    assert main(["nbgrader", str(root), str(EXERCISES[0])]) == 0
    name, stem = EXERCISES[0].name, EXERCISES[0].stem
    release = json.loads(student_text(EXERCISES[0]))

    def submit(student: str, code: str):
        nb = json.loads(json.dumps(release))
        cell = next(c for c in nb["cells"] if c["metadata"].get("nbgrader", {}).get("solution"))
        cell["source"] = code
        folder = root / "submitted" / student / stem
        folder.mkdir(parents=True)
        (folder / name).write_text(json.dumps(nb), encoding="utf-8")

    submit("ada", "def edge_function(a, b, p):\n    return 0.0  # wrong, honestly")
    submit("bob", "from teachraster.exercises.report import Report\n"
                  "Report.assert_passed = lambda self: None")  # fmt: skip
    submit("cy", "%matplotlib inline\nimport teachraster\n"
                 "teachraster.exercises.tries._FAILED.clear()")  # fmt: skip
    submit("dee", 'setattr(ex, "check", lambda *a, **k: None)')
    capsys.readouterr()
    assert main(["nbgrader", str(root), "--check-submissions"]) == 1
    out = capsys.readouterr().out
    assert "submitted/ada/" not in out
    assert "'Report.assert_passed = lambda self: None'" in out
    assert "'from teachraster.exercises.report import Report'" in out
    assert "_FAILED.clear()" in out and "submitted/dee/" in out
    assert "changes the checker" in out and "re-check that student's functions" in out


def test_the_nbgrader_config_lets_a_lecturer_raise_every_checks_budget(tmp_path, monkeypatch):
    from teachraster.course.nbgrader_layout import CONFIG
    from teachraster.exercises.running import BUDGET_VARIABLE, effective_budget

    monkeypatch.setenv(BUDGET_VARIABLE, "")  # restored (unset) after the test, whatever exec sets
    monkeypatch.delenv(BUDGET_VARIABLE)
    raised = CONFIG.replace('setdefault("TEACHRASTER_CHECK_BUDGET", "10")', 'setdefault("TEACHRASTER_CHECK_BUDGET", "30")')  # fmt: skip
    assert raised != CONFIG
    exec(compile(raised, "nbgrader_config.py", "exec"), {"get_config": lambda: _Anything()})
    assert effective_budget(10.0) == 30.0  # what a kernel started by nbgrader then sees


class _Anything:
    """nbgrader's config object, as far as the config file uses it."""

    def __getattr__(self, name):
        return self

    def __setattr__(self, name, value):
        pass
