"""Review r324 (lesson 12b): the standards table's llvmpipe column said a fixed-point target
"clamps" with nothing measured (C2); the explorer's count is tested in test_lines_views.py and
test_blending_r263.py (C1)."""

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


def test_llvmpipe_clamp_is_measured():
    """C2: §1's two results that leave [0, 1] go into an RGBA8 target on llvmpipe: every
    channel outside [0, 1] is stored clamped, the others within a code of §1's codes; a
    source red of 1.5 minus a stored 0.8 stores 1 − 0.8, so the inputs are clamped before the
    blend, as the table's GL column says (§17.3.6)."""
    text = _flat("blendrules")
    assert "| clamps, the inputs too: in §1's two results every channel that leaves [0, 1] is " \
        "stored clamped, the others within a code of §1's (llvmpipe rounds the source to 8 bits " \
        "first: alpha 0.5 to 128/255, which gives its codes exactly; GL asks only for the " \
        "destination's precision, §17.3.6.1); a source above 1 is clamped " \
        "before it is subtracted (the cell above) |" in text  # fmt: skip
    assert "into an `RGBA8` target (8-bit UNORM" in _flat("glorder_md")
    nsb = lesson("12b_blending")
    if not nsb.ok:
        pytest.skip("no OpenGL context")
    assert set(nsb.gl_clamp) == {"additive", "FUNC_REVERSE_SUBTRACT"}
    assert all(clamped and apart <= 1 for clamped, apart in nsb.clamp_apart.values())
    rules = nsb.sub_rules
    assert nsb.gl_sub == rules["source clamped first"] != rules["unclamped"]
    printed = streams(executed("12b_blending").notebook())
    assert "the channels outside [0, 1] stored clamped, at most" in printed
    assert f"red 1.5 minus a stored 0.8 into RGBA8 on llvmpipe: code {nsb.gl_sub}" in printed


def test_api_state_of_the_transparent_pass_and_d3d_sections():
    """M1: blending is off until enabled, and the state of the transparent pass (enable,
    factors, operator, depth mask, write mask) API by API. M3: the Direct3D column cites
    D3D11.3's sections for per-sample blending, sRGB targets and clamping."""
    state = _flat("blendstate")
    assert state.startswith("**The state of that transparent pass, API by API.**")
    for name in ("`glEnable(GL_BLEND)`", "`glEnablei(GL_BLEND, i)`", "`BlendEnable`",
                 "`blendEnable`", "`glColorMask`", "`RenderTargetWriteMask`", "`colorWriteMask`",
                 "`glDepthMask(GL_FALSE)`", "D3D11_DEPTH_WRITE_MASK_ZERO",
                 "`depthWriteEnable = VK_FALSE`", "§17.1 *Blend State*"):  # fmt: skip
        assert name in state, name
    cells = [c.get("id") for c in json.loads(NB.read_text())["cells"]]
    assert cells.index("blendstate") == cells.index("depthwrite") + 1
    table = _flat("blendrules")
    for section in ("§3.5.4 *Effects of Sample Count > 1*", "§17.4 *Gamma Correction*",
                    "§17.5 *Blending Precision*", "§4.2 *Fixed Order of Pipeline Results*"):  # fmt: skip
        assert section in table, section


def test_small_items_r324():
    """S1: the simulator's depth buffers leave the lesson text for a code comment; S2: the
    WBOIT takeaway is stated once; S4: alpha to coverage's figure has a key."""
    assert "The package's render has one depth buffer" not in _flat("oit")
    cells = {c.get("id"): "".join(c["source"]) for c in json.loads(NB.read_text())["cells"]}
    assert "# render has one depth buffer" in cells["peel"]
    assert _flat("oit_whymd").count("exact only where") == 1
    assert 'label="sample kept (written)"' in cells["a2cfig01"]
    assert 'label="sample dropped"' in cells["a2cfig01"]


def test_premultiplied_mipmaps():
    """M4: the mip pyramid averages as the bilinear filter does: level 1's half-covered edge
    texels darken over white with straight alpha, not premultiplied."""
    nsb = lesson("12b_blending")
    assert round(float(nsb.mip_red["straight"]), 3) == 0.75 and nsb.mip_red["premultiplied"] == 1
    printed = streams(executed("12b_blending").notebook())
    assert "their red over white:\n  straight 0.750, premultiplied 1.000 (right: 1.000)" in printed
    assert "`tr.mipmap`" in _flat("1627c17b")
