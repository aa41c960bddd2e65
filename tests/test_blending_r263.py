"""Review r263 (lesson 12b, round 29): the blend state in the explorer (M3), layers grouped
offscreen, straight against premultiplied (M2), the standards table of the blend rules (M1),
llvmpipe's drift measured against the exact composite (S1) and the small items."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from notebook_runs import executed, lesson, streams

pytestmark = [pytest.mark.filterwarnings("ignore::DeprecationWarning"), pytest.mark.notebook]
NB = Path(__file__).resolve().parents[1] / "notebooks" / "12b_blending.ipynb"


def _flat(cid: str) -> str:
    cells = json.loads(NB.read_text())["cells"]
    return " ".join("".join(next(c for c in cells if c.get("id") == cid)["source"]).split())


@pytest.fixture(scope="module")
def nsb():
    return lesson("12b_blending")


def test_grouped_layers_straight_against_premultiplied(nsb):
    """M2: B and C composited into a layer cleared to (0, 0, 0, 0), then onto white, then A:
    premultiplied gives the direct picture (associative, Porter and Duff 1984), straight alpha
    is off by 0.24 and its layer stores 0.36 where C alone covers (a·a), not 0.6."""
    text = _flat("groupmd")
    assert "Porter and Duff, *Compositing Digital Images*, SIGGRAPH 1984" in text
    assert "**associative**" in text and "alpha 0.6" in text and nsb.disc_alpha == 0.6
    straight, premult = nsb.grouping[False], nsb.grouping[True]
    assert round(straight[3], 2) == 0.24 and premult[3] < 1e-15
    assert round(float(straight[1][nsb.only_c][3]), 2) == 0.36
    assert round(float(premult[1][nsb.only_c][3]), 2) == 0.6
    printed = streams(executed("12b_blending").notebook())
    assert "straight: grouped minus direct, RGB up to 0.24;" in printed
    assert "the layer's alpha under C alone 0.36 (C's alpha 0.6)" in printed
    assert "Porter and Duff 1984" in _flat("f26a5112")


def test_blend_rules_table(nsb):
    """M1: ordering, per-sample blending, the sRGB target's linear blending (and GL's enable),
    fixed-point clamping: GL, Direct3D, Vulkan, llvmpipe, teachraster with their sections."""
    text = _flat("blendrules")
    header = "| rule | GL 4.6 | Direct3D 10/11/12 | Vulkan | llvmpipe | teachraster |"
    assert header in text
    for rule in ("submission order", "per sample under MSAA", "sRGB target blends in linear",
                 "fixed-point target clamps"):  # fmt: skip
        assert rule in text, rule
    assert "§2.1 *Execution Model*" in text and "*Fixed Order of Pipeline Results*" in text
    assert "*Additional Multisample Fragment Operations*" in text
    assert "`GL_FRAMEBUFFER_SRGB` **enabled**" in text and "no enable to forget" in text
    assert "§17.3.6" in text and "§17.3.7" in text and "§2.3.5.2" in text


def test_llvmpipe_drift_against_the_exact_composite(nsb):
    """S1: the cell prints each target's codes minus the exact composite (float64, clamped per
    layer, never rounded): teachraster's rounding stays within 0.12 of a code on average, up
    to 5.1 after 40 additive layers; llvmpipe's several codes there are its own. Review r387
    C1: llvmpipe's mean is +6.81 on one machine and +6.88 on another (its fast sRGB
    conversions take other code paths on other CPUs), so the text quotes no digits of it and
    the printed row is checked against the values the cell computed."""
    text = _flat("srgbglmd")
    assert "**exact composite**" in text and "within 0.12 of a code" in text
    assert (
        "up to 5.1 codes" in text and "several codes (the last column of the 40-layer row)" in text
    )
    assert "6.81" not in text and "6.88" not in text
    if not nsb.ok:
        pytest.skip("no OpenGL context")
    exact = nsb.srgb_exact
    assert max(abs(v["ours"][0]) for v in exact.values()) <= 0.125
    assert round(exact[("additive", 40)]["ours"][1], 1) == 5.1
    gl_mean, gl_largest = exact[("additive", 40)]["llvmpipe"]
    assert 3 <= gl_mean <= 10  # "several codes", brighter
    printed = streams(executed("12b_blending").notebook())
    # review r324 S3: one table, in codes (the lines said "steps" and "codes" for one thing)
    row = next(line for line in printed.splitlines() if line.startswith("40 'additive'"))
    assert "+0.12 ( 5.1)" in row and row.endswith(f"{gl_mean:+12.2f} ({gl_largest:4.1f})")
    assert "steps on average" not in printed and "mean (largest)" in printed


def test_explorer_blend_state_in_the_lesson(nsb):
    """M3: the explorer's blend state. Review r324 C1: "additive and multiply give 0 differing
    pixels in any order" hid multiply's last bits (§2's cell prints them) and the sRGB
    framebuffer's codes; the count now counts every difference, as §2's cells do, and says
    how far: only rounding for additive and multiply, in float and in sRGB, where at the
    explorer's start each of the two differs somewhere; "over" by far more, its 600."""
    gaps = nsb.mode_gap
    assert all(gaps[(m, s)].rounding for m in ("additive", "multiply") for s in (False, True))
    assert gaps[("additive", False)].differ > 0 and gaps[("multiply", True)].differ > 0
    assert gaps[("over", False)].differ == nsb.explorer_differ and not gaps[("over", True)].rounding
    printed = streams(executed("12b_blending").notebook())
    for (mode, srgb), gap in gaps.items():
        line = (
            f"  {mode!r}, {'sRGB framebuffer' if srgb else 'float'}: {gap.differ} pixel(s) differ"
        )
        assert line + (f"\n    {gap.words()[2:]}" if gap.differ else "\n") in printed
    text = _flat("tryit")
    assert '**"blend"** and **"alpha"** are the blend state of §1' in text
    assert "no pixel differs in any order" not in text and "only by rounding, as §2 found" in text
    assert "in float some pixels differ in their last bits" in text


def test_small_items_r263():
    """S2: the GPU's depth-peeling test stated (a shader compare and discard); S3: the order
    paragraph split; S4: WBOIT's takeaway first."""
    assert "bound as a texture, and discards a fragment not behind it" in _flat("oit")
    cells = json.loads(NB.read_text())["cells"]
    order = "".join(next(c for c in cells if c.get("id") == "a8d65864")["source"])
    assert order.count("\n\n") >= 3
    assert _flat("oit_whymd").startswith("In short: WBOIT is exact only where")


def test_llvmpipe_column_is_measured_r275(nsb):
    """Review r275 C2: the table's llvmpipe column cited evidence the lesson never produced;
    a cell now draws §2's two orders (three runs each) and §5's 4-sample blend on llvmpipe,
    and the table cites that cell. Without GL the cell says so, as the other llvmpipe cell."""
    text = _flat("blendrules")
    assert "§2's pictures are the same run after run" not in text and "(§6's table)" not in text
    assert "each drawn three times, give the same pictures every run" in text
    assert "matches `render`'s per-sample blend, not one blend per pixel" in text
    printed = streams(executed("12b_blending").notebook())
    if not nsb.ok:
        assert "no OpenGL here:" in printed
        pytest.skip("no OpenGL context")
    assert nsb.gl_order_differ == nsb.over_differ == 642
    for order in ("0 → 1 → 2", "2 → 1 → 0"):
        assert f"§2 drawn {order} on llvmpipe: the 3 runs identical;\n  minus render at most" in (
            printed
        )
    assert "the two orders on llvmpipe: 642 pixels differ (render: 642)" in printed
    off = nsb.gl_msaa_off
    assert off["per sample, then the mean (render)"] < 1e-6 < off["one blend per pixel"]
    assert f"one blend per pixel at most {off['one blend per pixel']:.1e}" in printed
