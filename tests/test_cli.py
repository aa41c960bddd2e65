"""The classroom command line: every subcommand writes what its suffix says, animations have
one frame per shown step, long exports show a progress bar, bad arguments exit 2 naming the
option, MP4 needs ffmpeg (and says so), and the core stays free of matplotlib."""

import matplotlib

matplotlib.use("Agg")  # as MPLBACKEND=Agg: the exports never open a window

import json  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import shutil  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
from pathlib import Path  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from PIL import Image  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster import cli  # noqa: E402
from teachraster.pipeline.scenes import SCENES  # noqa: E402
from teachraster.plotting import FillView  # noqa: E402
from teachraster.study.hardcases import CASES  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
XY = "2.2,1.5 13.7,5.2 5.1,12.8"
# small exports keep the whole module well under its time budget
FAST = ["--dpi", "30"]


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def run(*argv) -> int:
    return cli.main([str(a) for a in argv])


def n_steps(method="span", size=(16, 16), w=None) -> int:
    tri = tr.Triangle(cli.parse_xy(XY), w=w)
    return len(tr.rasterize(tri, *size, method=method, trace=True).trace)


def png_size(path: Path) -> tuple[int, int]:
    """(width, height) from the PNG's own header (IHDR), checking the signature first."""
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE, f"{path.name} is not a PNG"
    assert data[12:16] == b"IHDR"
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def gif_frames(path: Path) -> tuple[int, list[int]]:
    """Number of frames of a GIF and the duration (ms) of each."""
    with Image.open(path) as im:
        assert im.format == "GIF"
        durations = []
        for i in range(im.n_frames):
            im.seek(i)
            durations.append(im.info["duration"])
        return im.n_frames, durations


# -- fill ------------------------------------------------------------------------------------
def test_fill_png_is_a_png_of_the_figure_size(tmp_path, capsys):
    out = tmp_path / "fill.png"
    assert run("fill", "--xy", XY, "-o", out, "--dpi", 40) == 0
    # FillView's figure is 12 x 9.5 inches
    assert png_size(out) == (480, 380)
    with Image.open(out) as im:
        im.verify()
    n = n_steps()
    assert f"step {n - 1} of {n - 1}" in capsys.readouterr().out  # the finished fill


def test_fill_png_of_one_step(tmp_path, capsys):
    out = tmp_path / "step.png"
    assert run("fill", "--xy", XY, "--method", "halfplane", "--step", 7, "-o", out, *FAST) == 0
    assert png_size(out)[0] > 0
    assert "step 7 of" in capsys.readouterr().out


def test_fill_png_default_resolution_is_for_slides(tmp_path):
    out = tmp_path / "slide.png"
    assert run("fill", "--xy", XY, "--size", "8x8", "-o", out) == 0
    assert png_size(out) == (12 * cli.PNG_DPI, int(9.5 * cli.PNG_DPI))


@pytest.mark.parametrize("every", [1, 3])
def test_fill_gif_has_one_frame_per_shown_step_and_holds_the_last(tmp_path, capsys, every):
    out = tmp_path / "fill.gif"
    assert (
        run("fill", "--xy", XY, "--every", every, "--fps", 4, "--hold", 1.5, "-o", out, *FAST) == 0
    )
    n = n_steps()
    shown = len(range(0, n, every)) + ((n - 1) % every != 0)  # the last step always shown
    frames, durations = gif_frames(out)
    assert frames == shown
    # the held repeats of the finished fill merge into one long last frame (1 + 6 frames)
    assert durations[0] == 250
    assert durations[-1] == 7 * 250
    err = capsys.readouterr().err
    total = shown + 6
    assert f"{total}/{total} frames" in err and "[" + "#" * 30 + "]" in err
    assert "0/" in err  # the bar starts empty, so a long export shows progress at once


def test_fill_gif_halfplane_every_and_size(tmp_path):
    out = tmp_path / "hp.gif"
    argv = ["fill", "--xy", XY, "--size", "16x12", "--method", "halfplane", "--every", 10]
    assert run(*argv, "-q", "-o", out, *FAST) == 0
    n = n_steps("halfplane", size=(16, 12))
    assert gif_frames(out)[0] == math.ceil(n / 10) + ((n - 1) % 10 != 0)
    with Image.open(out) as im:
        assert im.size == (360, 285)  # 12 x 9.5 inches at 30 dpi


def test_animation_updates_the_view_in_place(tmp_path, monkeypatch):
    """Each frame is FillView.show_step(k, draw=False) on one view, never a new figure."""
    calls, views = [], []
    real_show, real_init = FillView.show_step, FillView.__init__

    def spy_show(self, k, *, draw=True):
        calls.append((k, draw))
        return real_show(self, k, draw=draw)

    def spy_init(self, *a, **kw):
        views.append(self)
        real_init(self, *a, **kw)

    monkeypatch.setattr(FillView, "show_step", spy_show)
    monkeypatch.setattr(FillView, "__init__", spy_init)
    assert run("fill", "--xy", XY, "-q", "-o", tmp_path / "a.gif", *FAST) == 0
    n = n_steps()
    assert len(views) == 1
    frame_calls = calls[-n:]
    assert frame_calls == [(k, False) for k in range(n)]


def test_quiet_gif_prints_no_progress(tmp_path, capsys):
    assert run("fill", "--xy", XY, "-q", "--every", 5, "-o", tmp_path / "q.gif", *FAST) == 0
    assert "frames" not in capsys.readouterr().err


def test_progress_bar_text():
    import io

    stream = io.StringIO()
    bar = cli.Progress(4, "x.gif", stream=stream, width=8)
    for k in range(5):
        bar.update(k)
    bar.close()
    text = stream.getvalue()
    assert "[--------] 0/4 frames  x.gif" in text
    assert "[####----] 2/4 frames" in text
    assert text.endswith("[########] 4/4 frames  x.gif\n")


# -- compare ---------------------------------------------------------------------------------
def test_compare_png_reports_the_maximum_error(tmp_path, capsys):
    out = tmp_path / "cmp.png"
    assert run("compare", "--xy", XY, "--w", "1,4,2", "--attr", "u=0,1,0", "-o", out, *FAST) == 0
    assert png_size(out)[0] > png_size(out)[1]  # three panels side by side
    text = capsys.readouterr().out
    assert "max |affine - perspective| = " in text
    assert float(text.rsplit("= ", 1)[1]) > 0.05  # unequal w: affine visibly wrong


def test_compare_vector_attribute_and_show(tmp_path, capsys):
    out = tmp_path / "uv.png"
    argv = [
        "compare",
        "--xy",
        XY,
        "--w",
        "1,3,2",
        "--attr",
        "uv=0,0 1,0 0,1",
        "--attr",
        "s=0,1,0",
        "--show",
        "s",
    ]
    assert run(*argv, "-o", out, *FAST) == 0
    assert "max |affine" in capsys.readouterr().out


def test_compare_gif_sweeps_w(tmp_path, capsys):
    out = tmp_path / "sweep.gif"
    assert (
        run(
            "compare",
            "--xy",
            XY,
            "--sweep-w",
            "1:8",
            "--vertex",
            1,
            "--frames",
            5,
            "-o",
            out,
            *FAST,
        )
        == 0
    )
    frames, _ = gif_frames(out)
    assert frames == 5  # w changes every frame, so no two frames merge
    captured = capsys.readouterr()
    assert "w2 from 1 to 8" in captured.out  # --vertex 1 is v2 (indices from 0)
    assert "frames" in captured.err


# -- scene, case, list -----------------------------------------------------------------------
def test_scene_png_and_plan(tmp_path, capsys):
    out = tmp_path / "floor.png"
    assert run("scene", "textured_floor", "--size", "64x48", "-o", out, *FAST) == 0
    w, h = png_size(out)
    assert w > h
    text = capsys.readouterr().out
    assert "textured_floor:" in text and "clipping" in text and "perspective" in text


def test_scene_compare(tmp_path, capsys):
    out = tmp_path / "floorc.png"
    argv = ["scene", "textured_floor", "--size", "40x30", "--interpolation", "affine"]
    assert run(*argv, "--compare", "-o", out, *FAST) == 0
    assert png_size(out)[0] > 2 * png_size(out)[1]
    text = capsys.readouterr().out
    assert "effect" in text
    # a textured scene compares where the samples land, in texels, not the two-tone colours
    assert "max texel error = " in text
    error = float(text.split("max texel error = ")[1].split()[0])
    assert error > 1.0


def test_scene_compare_texel_error_matches_texture_module(tmp_path, monkeypatch):
    from teachraster.pipeline.render_scenes import render_scene
    from teachraster.pipeline.scenes import get_scene
    from teachraster.pipeline.texture import texel_error
    from teachraster.plotting import ComparisonView

    views = []
    original = ComparisonView.__init__

    def spy(self, *args, **kwargs):
        original(self, *args, **kwargs)
        views.append(self)

    monkeypatch.setattr(ComparisonView, "__init__", spy)
    argv = ["scene", "textured_floor", "--size", "40x30", "--compare"]
    assert cli.main([*argv, "-o", str(tmp_path / "f.png"), *FAST]) == 0
    scene = get_scene("textured_floor")
    uv = {
        mode: render_scene(scene, width=40, height=30, interpolation=mode).attr("uv")
        for mode in ("affine", "perspective")
    }
    expected = np.nanmax(texel_error(uv["affine"], uv["perspective"], scene.texture.shape))
    assert views[0].maximum == pytest.approx(expected)


def test_scene_compare_untextured_keeps_colour_difference(tmp_path, capsys):
    out = tmp_path / "cube.png"
    assert run("scene", "cube", "--size", "40x30", "--compare", "-o", out, *FAST) == 0
    assert "max |affine - perspective| = " in capsys.readouterr().out


@pytest.mark.parametrize(
    "name",
    ["d3d_split_square", "sliver_pair", "behind_camera", "stepping_drift", "coplanar_overlap"],
)
def test_case_png(tmp_path, capsys, name):
    out = tmp_path / f"{name}.png"
    assert run("case", name, "-o", out, *FAST) == 0
    assert png_size(out)[0] > 0
    text = capsys.readouterr().out
    assert "check:  passed" in text
    if CASES[name].has_naive:
        assert "naive:" in text


def test_case_with_method(tmp_path, capsys):
    assert run("case", "flat_top", "--method", "halfplane", "-o", tmp_path / "c.png", *FAST) == 0
    assert "naive coverage differs" in capsys.readouterr().out


def test_list_names_every_scene_and_case(capsys):
    assert run("list") == 0
    text = capsys.readouterr().out
    for name in [*SCENES, *CASES]:
        assert f"  {name} " in text


def test_python_m_teachraster_list():
    out = subprocess.run(
        [sys.executable, "-m", "teachraster", "list"],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=60,
    )
    assert out.returncode == 0, out.stderr
    assert "textured_floor" in out.stdout and "d3d_split_square" in out.stdout


def test_python_m_teachraster_help():
    out = subprocess.run(
        [sys.executable, "-m", "teachraster", "fill", "-h"],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=60,
    )
    assert out.returncode == 0
    assert "--xy" in out.stdout and "--every" in out.stdout


# -- bad input -------------------------------------------------------------------------------
BAD = [
    (["fill", "--xy", "1,2 3,4", "-o", "a.png"], "--xy"),
    (["fill", "--xy", "1,2 3,x 5,6", "-o", "a.png"], "--xy"),
    (["fill", "--xy", XY, "--w", "1,0,2", "-o", "a.png"], "--w"),
    (["fill", "--xy", XY, "--w", "1,2", "-o", "a.png"], "--w"),
    (["fill", "--xy", XY, "--size", "0x4", "-o", "a.png"], "--size"),
    (["fill", "--xy", XY, "--size", "big", "-o", "a.png"], "--size"),
    (["fill", "--xy", XY, "--method", "scanline", "-o", "a.png"], "--method"),
    (["fill", "--xy", XY, "--interpolation", "cubic", "-o", "a.png"], "--interpolation"),
    (["fill", "--xy", XY, "--every", "0", "-o", "a.gif"], "--every"),
    (["fill", "--xy", XY, "--fps", "-2", "-o", "a.gif"], "--fps"),
    (["fill", "--xy", XY, "--step", "999", "-o", "a.png"], "--step"),
    (["fill", "--xy", XY, "--step", "2", "-o", "a.gif"], "--step"),
    (["fill", "--xy", XY, "--style", "neon", "-o", "a.png"], "--style"),
    (["fill", "--xy", XY, "-o", "a.jpg"], "-o/--output"),
    (["fill", "--xy", XY, "-o", "no/such/folder/a.png"], "-o/--output"),
    (["fill", "-o", "a.png"], "--xy"),
    (["compare", "--xy", XY, "--attr", "u=0,1", "-o", "a.png"], "--attr"),
    (["compare", "--xy", XY, "--attr", "0,1,2", "-o", "a.png"], "--attr"),
    (["compare", "--xy", XY, "--show", "v", "-o", "a.png"], "--show"),
    (["compare", "--xy", XY, "--sweep-w", "1:8", "-o", "a.png"], "--sweep-w"),
    (["compare", "--xy", XY, "--sweep-w", "0:8", "-o", "a.gif"], "--sweep-w"),
    (["compare", "--xy", XY, "--vertex", "3", "-o", "a.gif"], "--vertex"),
    (["scene", "teapot", "-o", "a.png"], "NAME"),
    (["scene", "cube", "-o", "a.gif"], "-o/--output"),
    (["case", "nope", "-o", "a.png"], "NAME"),
    (["case", "coplanar_overlap", "--method", "span", "-o", "a.png"], "--method"),
    (["frobnicate"], "COMMAND"),
]


@pytest.mark.parametrize("argv, option", BAD, ids=[" ".join(a[:1] + [o]) for a, o in BAD])
def test_bad_input_exits_2_naming_the_option(tmp_path, capsys, monkeypatch, argv, option):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as exc:
        cli.main(argv)
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert option in err and "error:" in err
    assert "Traceback" not in err
    assert not list(tmp_path.iterdir()), "nothing is written on bad input"


def test_no_command_exits_2(capsys):
    with pytest.raises(SystemExit) as exc:
        cli.main([])
    assert exc.value.code == 2
    assert "COMMAND" in capsys.readouterr().err


def test_write_failure_is_one_line_not_a_traceback(tmp_path, capsys):
    target = tmp_path / "taken.png"
    target.mkdir()  # a folder where the file should go
    assert run("fill", "--xy", XY, "-o", target, *FAST) == 1
    err = capsys.readouterr().err
    assert err.startswith("teachraster fill: error:") and "Traceback" not in err


# -- MP4 -------------------------------------------------------------------------------------
def test_mp4_without_ffmpeg_says_install_it_or_use_gif(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(cli.run, "ffmpeg_available", lambda: False)
    out = tmp_path / "a.mp4"
    with pytest.raises(SystemExit) as exc:
        cli.main(["fill", "--xy", XY, "-o", str(out)])
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert "-o/--output" in err and "ffmpeg" in err and "install" in err and ".gif" in err
    assert not out.exists()


STAND_IN_FFMPEG = """#!{python}
import json, sys
# Records what matplotlib's FFMpegWriter asks for and how many bytes of frames it sends.
data = sys.stdin.buffer.read()
args = sys.argv[1:]
with open(args[-1], "wb") as f:
    f.write(b"stand-in")
with open({log!r}, "w") as f:
    json.dump({{"args": args, "bytes": len(data)}}, f)
"""


def test_mp4_plumbing_with_a_stand_in_ffmpeg(tmp_path, monkeypatch):
    """The MP4 path drives FFMpegWriter (h264, the fps asked for, every frame piped)."""
    bin_dir, log = tmp_path / "bin", tmp_path / "ffmpeg.json"
    bin_dir.mkdir()
    fake = bin_dir / "ffmpeg"
    fake.write_text(STAND_IN_FFMPEG.format(python=sys.executable, log=str(log)))
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}")
    monkeypatch.setitem(matplotlib.rcParams, "animation.ffmpeg_path", "ffmpeg")
    out = tmp_path / "fill.mp4"
    assert run("fill", "--xy", XY, "--fps", 5, "--hold", 1, "-q", "-o", out, "--dpi", 20) == 0
    record = json.loads(log.read_text())
    args = record["args"]
    out_args = args[args.index("-i") + 2 :]  # after the piped raw input
    assert out_args[out_args.index("-vcodec") + 1] == "h264"
    assert out_args[out_args.index("-pix_fmt") + 1] == "yuv420p"  # plays everywhere
    assert float(args[args.index("-framerate") + 1]) == 5
    w, h = (int(v) for v in args[args.index("-s") + 1].split("x"))
    frames = n_steps() + 5  # every step, then the finished fill held for 1 s at 5 fps
    assert record["bytes"] == frames * w * h * 4  # RGBA frames
    assert out.read_bytes() == b"stand-in"


@pytest.mark.skipif(
    shutil.which("ffmpeg") is None and not os.environ.get("TEACHRASTER_REQUIRE_FFMPEG"),
    reason="ffmpeg is not installed (Debian: apt-get install ffmpeg); "
    "MP4 export needs it, GIF does not",
)
def test_mp4_with_real_ffmpeg(tmp_path):
    assert shutil.which("ffmpeg"), "TEACHRASTER_REQUIRE_FFMPEG is set (CI) but ffmpeg is missing"
    out = tmp_path / "fill.mp4"
    assert run("fill", "--xy", XY, "--every", 4, "-q", "-o", out, *FAST) == 0
    data = out.read_bytes()
    assert data[4:8] == b"ftyp"  # an MP4 (ISO base media) file


# -- the core stays numpy-only ---------------------------------------------------------------
def test_import_teachraster_does_not_import_matplotlib():
    code = (
        "import sys\n"
        "import teachraster, teachraster.cli\n"
        "teachraster.cli.build_parser()\n"
        "assert teachraster.cli.main(['list']) == 0\n"
        "heavy = sorted({m.split('.')[0] for m in sys.modules} & {'matplotlib', 'PIL'})\n"
        "print('HEAVY', heavy)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=60,
        check=True,
    )
    assert out.stdout.strip().splitlines()[-1] == "HEAVY []"


def test_parsers_accept_separators():
    assert cli.parse_xy("1,2;3,4; 5,6").tolist() == [[1, 2], [3, 4], [5, 6]]
    name, values = cli.parse_attr("uv=0,0;1,0;0,1")
    assert name == "uv" and values.shape == (3, 2)
    assert cli.parse_size("32X24") == (32, 24)
    assert cli.parse_range("1:8") == (1.0, 8.0)
    np.testing.assert_array_equal(cli.parse_w("1, 2, 4"), [1, 2, 4])


def test_gif_without_hold_and_in_the_default_style(tmp_path):
    out = tmp_path / "plain.gif"
    argv = ["fill", "--xy", XY, "--hold", "0", "--style", "default", "--every", 4, "-q"]
    assert run(*argv, "-o", out, *FAST) == 0
    frames, durations = gif_frames(out)
    assert frames == len(range(0, n_steps(), 4)) + ((n_steps() - 1) % 4 != 0)
    assert set(durations) == {250}  # no held last frame
