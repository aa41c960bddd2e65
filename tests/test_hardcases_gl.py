"""The hard-case catalogue's coverage cases against a real GPU rasteriser: Mesa's llvmpipe
(moderngl + EGL). Lesson 07 shows llvmpipe's owners beside ours on its four meshes; here every
case the picker holds is drawn, and every pixel's fragment count and last writer must equal
ours. Skipped, with the reason, where no OpenGL context can be made."""

from __future__ import annotations

import numpy as np
import pytest
from gl_required import require_gl

require_gl()

from teachraster.study import hardcases
from teachraster.study.opengl_owners import gl_owners, window_to_clip
from teachraster.widgets.case_picker import screen_cases

pytestmark = pytest.mark.gl


@pytest.mark.parametrize("name", screen_cases())
def test_llvmpipe_draws_every_coverage_case_as_ours(name):
    """Every pixel gets as many fragments from llvmpipe as our triangles cover its centre
    (so no centre of a mesh twice, none lost), and its last writer is our last triangle
    covering it: on the meshes, the owner of every pixel is the same."""
    case = hardcases.get_case(name)
    width, height = case.inputs["size"]
    fills = case.run().fills
    counts = np.sum([f.coverage for f in fills], axis=0, dtype=np.int64)
    last = np.full(counts.shape, -1, dtype=np.int64)
    for k, f in enumerate(fills):
        last[f.coverage] = k
    gl = gl_owners(case.triangles, width, height)
    assert np.array_equal(gl.fragments, counts), np.argwhere(gl.fragments != counts)[:6]
    assert np.array_equal(gl.owner, last), np.argwhere(gl.owner != last)[:6]
    if case.kind == "mesh":
        assert gl.fragments.max() == 1


def test_window_to_clip_inverts_the_viewport():
    xy = np.array([[[0.5, 0.5], [13.25, 3.5], [4.75, 11.5]]])
    clip = window_to_clip(xy, 20, 16)
    back = np.stack([(clip[..., 0] + 1) * 10, (1 - clip[..., 1]) * 8], axis=-1)
    assert np.allclose(back, xy, atol=1e-12) and (clip[..., 3] == 1).all()
    with pytest.raises(ValueError, match="xy"):
        window_to_clip(xy[0], 20, 16)
