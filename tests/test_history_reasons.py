"""The pixel history says the true reason (issue 28), checked against independent geometry.

Every "not_covered" record of a frame is checked against the *input* triangle, computed here
in float64 from its clip-space vertices, never from the renderer's pieces:

- "outside_edge" / "top_left" naming Eab: the point lies outside (or on) the input edge from
  va to vb, walked as CONVENTIONS name it (E12, E23, E31, or E13, E32, E21 for a triangle
  walked the other way), by the distance the record gives;
- "seam": the input triangle covers the point (inside its three edges, between near and
  far), and the piece named across the seam covers that very sample;
- "clipped_away": the triangle does not cover the point inside the image (the point is
  beyond near or far, or outside the triangle);
- "zero_area": the snapped corners of the piece are collinear.

Also: the values a history gives equal those the frame wrote, bit for bit, with every
``force``; Hi-Z rejections carry no values; integer arguments refuse bools.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from test_render import clip_from_window

import teachraster as tr
from teachraster.pipeline.debugging.edge_names import PLANES
from teachraster.pipeline.debugging.frame_history import REASONS

W, H = 24, 18
FORWARD, BACKWARD = {"E12", "E23", "E31"}, {"E13", "E32", "E21"}
CORNER = r"(v[123]|(E\d\d|near|far|guard \w+)(∩(E\d\d|near|far|guard \w+))*)"
SEAM = re.compile(rf"seam {CORNER}–{CORNER}$")


def window_of(clip):
    """(3, 2) window x, y and (3,) NDC z of an input triangle with every w > 0."""
    w = clip[:, 3]
    x = (clip[:, 0] / w + 1) * W / 2
    y = (1 - clip[:, 1] / w) * H / 2
    return np.stack([x, y], axis=1), clip[:, 2] / w


def cross(a, b, c):
    """E(a, b, c): twice the signed area of triangle a, b, c (y down)."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def edge_distance(xy, a, b, p):
    """Signed distance of p from the directed edge a -> b (positive: interior side, y down)."""
    return cross(xy[a], xy[b], p) / np.hypot(*(xy[b] - xy[a]))


def on_triangle(clip, p):
    """Barycentrics (3,) of the point of the input triangle's plane seen at window p, and its
    NDC z: the ray through p meets the plane at sum(alpha_i v_i) with w = 1."""
    xn, yn = 2 * p[0] / W - 1, 1 - 2 * p[1] / H
    alpha = np.linalg.solve(clip[:, [0, 1, 3]].T, [xn, yn, 1.0])
    return alpha, float(alpha @ clip[:, 2])


def check_reasons(frame, clip, tol=0.02, bits=8):
    """Every not_covered record of every pixel against the input triangles (module doc).

    Where a triangle has a vertex behind the eye (w <= 0) it has no window position: the
    claims are checked on the barycentrics of the point of its plane seen at the point."""
    offsets = np.array([[0.5, 0.5]]) if frame.samples is None else frame.samples
    counts = dict.fromkeys(REASONS, 0)
    for row in range(H):
        for col in range(W):
            h = frame.history(row, col)
            by_key = {(r.piece, r.sample): r for r in h}
            for r in h:
                where = f"pixel ({row}, {col}) sample {r.sample}:\n{h}"
                assert "->" not in str(h), where
                if r.outcome != "not_covered":
                    continue
                counts[r.reason] += 1
                p = np.array([col, row]) + offsets[r.sample]
                check_record(frame, r, clip[r.triangle], p, by_key, tol, bits, where)
    return counts


def check_record(frame, r, tri, p, by_key, tol, bits, where):
    """One not_covered record ``r`` at window point ``p`` against its input triangle."""
    seen = tri[:, 3] > 0  # every vertex in front of the eye: window positions exist
    xy = window_of(tri)[0] if seen.all() else None
    if r.reason in ("outside_edge", "top_left"):
        a, b = int(r.edge[1]) - 1, int(r.edge[2]) - 1
        if xy is None:  # outside (or on) ab, up to snapping
            alpha = on_triangle(tri, p)[0]
            assert alpha[3 - a - b] <= 1e-2 * np.abs(alpha).max(), where
        else:
            backwards = cross(*xy) < 0
            assert r.edge in (BACKWARD if backwards else FORWARD), where
            d = edge_distance(xy, a, b, p)
            # (a clipped piece's edge may end at a snapped new corner: a short one turns a
            # little, which moves it more far from its ends)
            assert d <= tol and abs(-d - r.outside) <= tol + 0.3 * abs(d), where
        assert (r.outside == 0) == (r.reason == "top_left"), where
    elif r.reason == "seam":
        assert SEAM.match(r.edge), where
        alpha, z = on_triangle(tri, p)  # the input triangle covers p (up to snapping)
        slack = 1e-2 if tol < 0.1 else 0.5  # coarse snapping moves a seam's ends in depth too
        assert -1 - slack <= z <= 1 + slack, where
        if xy is None:
            assert alpha.min() >= -1e-2 * np.abs(alpha).max(), where
        else:
            backwards = cross(*xy) < 0
            inside = [edge_distance(xy, *((a + 1) % 3, a)[:: 1 if backwards else -1], p)
                      for a in range(3)]  # fmt: skip
            assert min(inside) >= -tol, where
        assert_across(frame, r, by_key, bits, where)
    elif r.reason == "clipped_away":
        assert r.edge in PLANES, where
        alpha, z = on_triangle(tri, p)  # beyond near or far, or outside the triangle
        assert r.outside <= tol or not ((alpha > 1e-9).all() and -1 < z < 1), where
    elif r.reason == "turned_over":
        signs = snapped_signs(frame, r.triangle, bits)
        own, others = signs.pop(r.piece), np.array(list(signs.values()))
        assert own != 0 and (others == -own).any(), where
        assert_across(frame, r, by_key, bits, where)
    else:
        assert r.reason == "zero_area" and r.edge is None, where
        assert snapped_signs(frame, r.triangle, bits)[r.piece] == 0, where


def snapped_signs(frame, triangle, bits):
    """{piece: sign of its snapped area} for the pieces of an input triangle."""
    out = {}
    for piece in np.flatnonzero(frame.trace.parent == triangle):
        v = frame.trace.window[piece, :, :2]
        v = v if bits is None else np.round(v * 2**bits)  # snapped: half to even
        out[int(piece)] = np.sign(cross(*v))
    return out


def assert_across(frame, r, by_key, bits, where):
    """The piece named across covers the sample; none named: snapping turned one over."""
    if r.across >= 0:
        other = by_key[(r.across, r.sample)]
        assert other.outcome in ("hi_z", "failed_depth", "passed"), where
        assert frame.trace.parent[r.across] == r.triangle, where
    else:
        signs = np.array(list(snapped_signs(frame, r.triangle, bits).values()))
        assert (signs > 0).any() and (signs < 0).any(), where


def near_clipped_scene(rng, n=3):
    """Random triangles, some vertices in front of the near plane (window z < 0)."""
    xy = rng.uniform(-6, 30, (n, 3, 2))
    z = rng.uniform(-0.9, 0.9, (n, 3))
    w = rng.uniform(0.4, 3.0, (n, 3))
    return clip_from_window(xy, z, w, W, H)


@pytest.mark.parametrize("samples", [1, 4])
def test_near_clipped_pieces_name_the_seam_and_the_input_edges(rng, samples):
    total = dict.fromkeys(REASONS, 0)
    for _ in range(6 if samples == 1 else 3):
        clip = near_clipped_scene(rng)
        frame = tr.render(clip, W, H, trace=True, samples=samples)
        for reason, n in check_reasons(frame, clip).items():
            total[reason] += n
    assert total["seam"] > 0 and total["outside_edge"] > 0 and total["clipped_away"] > 0


def test_the_issue_case_a_seam_is_not_an_input_edge():
    """A centre well inside the input triangle, refused by one piece of it: the history
    names the seam between the pieces, not an edge of the input triangle."""
    clip = np.array([[[-0.5, -0.5, 0.0, 1.0], [0.6, -0.4, 0.2, 1.0], [0.0, 0.7, -3.0, 1.0]]])
    frame = tr.render(clip, 32, 24, trace=True)
    assert frame.trace.clip_status.tolist() == [1] and len(frame.trace.window) == 2
    h = frame.history(12, 17)
    miss, hit = h.records
    assert (miss.outcome, miss.reason, miss.across) == ("not_covered", "seam", 1)
    assert miss.edge == "seam v1–E32∩near" and hit.outcome == "passed"
    assert "clipping seam v1–E32∩near" in str(h) and "piece 1" in str(h)


def test_guard_band_trims_name_their_seams(rng):
    """Vertices millions of pixels away: the guard band trims the triangle into pieces whose
    seams cross the image; the history names them as seams, never as input edges."""
    seams = 0
    for samples in (1, 1, 4):
        xy = rng.uniform(0, 24, (2, 3, 2))
        xy[:, 0] = rng.choice([-1, 1], (2, 2)) * 4e7  # one vertex far beyond the guard band
        clip = clip_from_window(xy, rng.uniform(0.1, 0.9, (2, 3)), 1.0, W, H)
        frame = tr.render(clip, W, H, trace=True, samples=samples)
        assert (frame.trace.clip_status == 1).all()
        seams += check_reasons(frame, clip)["seam"]
    assert seams > 0


def test_walked_the_other_way_names_e13_e32_e21():
    xy = np.array([[2.0, 2.0], [20.0, 3.0], [4.0, 15.0]])
    for order, names in (([0, 1, 2], FORWARD), ([0, 2, 1], BACKWARD)):
        clip = clip_from_window(xy[order][None], 0.5, 1.0, W, H)
        frame = tr.render(clip, W, H, trace=True)
        seen = {r.edge for row in range(H) for col in range(W)
                for r in frame.history(row, col) if r.outcome == "not_covered"}  # fmt: skip
        assert seen == names
        check_reasons(frame, clip)
    # the centre (16.5, 2.5) lies above the edge from (2, 2) to (20, 3) (y = 2.81 there):
    # given v1, v2, v3 that edge is E12; given as v1, v3, v2 it is walked v1 -> v3: E13
    one = tr.render(clip_from_window(xy[None], 0.5, 1.0, W, H), W, H, trace=True)
    assert one.history(2, 16)[0].edge == "E12"
    other = tr.render(clip_from_window(xy[[0, 2, 1]][None], 0.5, 1.0, W, H), W, H, trace=True)
    assert other.history(2, 16)[0].edge == "E13"


@pytest.mark.parametrize("samples", [1, 4])
def test_zero_area_triangles_say_zero_area(samples):
    xy = np.array(
        [
            [[2, 2], [8, 8], [14, 14]],  # collinear
            [[3, 3], [3, 3], [12, 5]],  # two vertices the same
            [[4, 4], [12, 8.0005], [20, 12]],  # collinear only after snapping to 1/256 px
        ]
    )
    clip = clip_from_window(xy, 0.5, 1.0, W, H)
    frame = tr.render(clip, W, H, trace=True, samples=samples)
    assert frame.coverage.sum() == 0
    counts = check_reasons(frame, clip)
    assert counts["zero_area"] > 0 and sum(counts.values()) == counts["zero_area"]
    h = frame.history(8, 12)
    assert [r.reason for r in h if r.triangle == 2][0] == "zero_area"
    assert "zero area" in str(h) and "top-left" not in str(h)


def test_top_left_refusals_are_named_and_exact():
    """Two triangles sharing a diagonal through pixel centres: each centre on it goes to
    exactly one; the other's record says the top-left rule refused it on that edge."""
    xy = np.array(
        [[[0.5, 0.5], [16.5, 16.5], [0.5, 16.5]], [[0.5, 0.5], [16.5, 0.5], [16.5, 16.5]]]
    )
    clip = clip_from_window(xy, 0.5, 1.0, W, H)
    frame = tr.render(clip, W, H, trace=True)
    counts = check_reasons(frame, clip, tol=1e-9)
    # refused on an edge: the 16 centres of the shared diagonal (by one of the two), and the
    # 17 on the bottom edge y = 16.5 and the 17 on the right edge x = 16.5 (neither top nor
    # left); the top and left edges keep theirs
    assert counts["top_left"] == 16 + 17 + 17
    h = frame.history(4, 4)
    refused = [r for r in h if r.outcome == "not_covered"]
    assert len(refused) == 1 and refused[0].reason == "top_left" and refused[0].outside == 0
    assert f"on {refused[0].edge}" in str(h) and "top-left rule" in str(h)


# -- values: what was written, bit for bit ---------------------------------------------------
def mixed_scene(rng):
    """Perspective triangles beside constant-w ones (the renderer's batch holds both)."""
    a = clip_from_window(rng.uniform(0, 14, (3, 3, 2)), rng.uniform(0.2, 0.8, (3, 3)),
                         rng.uniform(0.5, 3.0, (3, 3)), W, H)  # fmt: skip
    b = clip_from_window(rng.uniform(8, 24, (3, 3, 2)), rng.uniform(0.2, 0.8, (3, 3)), 1.0, W, H)
    clip = np.concatenate([a, b, near_clipped_scene(rng, 2)])
    return clip, rng.uniform(-1, 1, (len(clip), 3, 3))


@pytest.mark.parametrize("force", [None, "perspective", "attributes", "all"])
def test_history_values_are_the_written_values_bit_for_bit(rng, force):
    for _ in range(3):
        clip, attrs = mixed_scene(rng)
        frame = tr.render(clip, W, H, attrs=attrs, trace=True, force=force)
        alone = [tr.render(clip[i : i + 1], W, H, attrs=attrs[i : i + 1], force=force)
                 for i in range(len(clip))]  # fmt: skip
        for row, col in np.argwhere(frame.overlay("overdraw") > 0):
            for r in frame.history(row, col):
                if r.outcome == "passed":
                    # what the triangle writes there is what it writes drawn alone
                    np.testing.assert_array_equal(r.value, alone[r.triangle].attrs[row, col])
                elif r.outcome in ("failed_depth", "hi_z"):
                    assert r.value == ()  # never interpolated: the outcome says why
                if r.shown:
                    np.testing.assert_array_equal(r.value, frame.attrs[row, col])


@pytest.mark.parametrize("force", [None, "perspective", "all"])
def test_msaa_history_values_are_the_written_values(rng, force):
    clip, attrs = mixed_scene(rng)
    frame = tr.render(clip, W, H, attrs=attrs, trace=True, force=force, samples=4)
    for row, col in np.argwhere(frame.triangle_id >= 0):
        for r in frame.history(row, col):
            if r.shown:
                np.testing.assert_array_equal(r.value, frame.sample_attrs[row, col, r.sample])
            if r.outcome in ("failed_depth", "hi_z"):
                assert r.value == ()  # a failed sample is not written: no value shown


def test_hi_z_rejections_carry_no_values():
    quad = np.array([[[0, 0], [32, 0], [0, 32]], [[32, 0], [32, 32], [0, 32]]], float)
    clip = np.concatenate([clip_from_window(quad, 0.2, width=32, height=32),
                           clip_from_window(quad, 0.7, width=32, height=32)])  # fmt: skip
    frame = tr.render(clip, 32, 32, attrs=np.ones((4, 3, 2)), trace=True)
    h = frame.history(20, 20)
    rejected = [r for r in h if r.outcome == "hi_z"]
    assert rejected and all(r.value == () for r in rejected)
    assert all(len(r.value) == 2 for r in h if r.outcome == "passed")


# -- arguments ---------------------------------------------------------------------------------
@pytest.mark.parametrize("row, col, name", [(True, 0, "row"), (0, False, "col"),
                                            (np.True_, 0, "row"), (1, np.False_, "col")])  # fmt: skip
def test_history_refuses_bools_naming_the_argument(row, col, name):
    frame = tr.render(clip_from_window([[[1, 1], [7, 1], [1, 7]]], 0.5, width=8, height=8), 8,
                      8, trace=True)  # fmt: skip
    with pytest.raises(TypeError, match=name):
        frame.history(row, col)
    assert frame.history(np.int8(1), np.uint16(1)).row == 1


@pytest.mark.parametrize("samples", [1, 4])
def test_behind_the_eye_forced_clipping_and_other_snapping(rng, samples):
    """Vertices behind the eye (no window position), every triangle through the clipper,
    4 sub-pixel bits and unsnapped floats: the same true reasons."""
    from test_render import random_clip

    total = dict.fromkeys(REASONS, 0)
    for bits, force, cross_planes in ((8, "all", True), (None, "clipping", True), (4, None, False)):
        clip = random_clip(rng, 3, cross=cross_planes)
        frame = tr.render(clip, W, H, trace=True, samples=samples, subpixel_bits=bits,
                          force=force)  # fmt: skip
        # 4 bits move a vertex by up to 1/32 px in x and y: an edge moves by about that,
        # more along a short edge, at a point far beyond its ends
        tol = 0.25 if bits == 4 else 0.02
        for reason, n in check_reasons(frame, clip, tol=tol, bits=bits).items():
            total[reason] += n
    assert total["outside_edge"] > 0


def test_a_piece_snapping_turned_over_leaves_no_false_claim():
    """With 4 sub-pixel bits a thin clipped piece can turn over (its snapped corners run the
    other way round). Its edges still bound the triangle, from the other side: a centre
    beyond the near plane and outside E31 is outside E31 (it was called "across the seam,
    covered by the other piece", which covered nothing there: found by a fuzzer)."""
    clip = np.array([[[-1.1413143155391454, 0.8369695946132166, -1.1111753736364425, 1.3768032553830427],
                      [-1.173224124994192, 0.0474499093092405, 0.22856501440634722, 1.9340897289103482],
                      [-2.828012415356525, 2.4438327537686635, -2.3273091672619244, 2.2724574447012285]]])  # fmt: skip
    for samples in (1, 4):
        frame = tr.render(clip, W, H, trace=True, subpixel_bits=4, samples=samples)
        assert sorted(snapped_signs(frame, 0, 4).values()) == [-1, 1]  # piece 1 turned over
        counts = check_reasons(frame, clip, tol=0.25, bits=4)
        assert counts["seam"] > 0 and counts["outside_edge"] > 0
    one = tr.render(clip, W, H, trace=True, subpixel_bits=4)
    assert [(r.reason, r.edge) for r in one.history(0, 0)] == [("outside_edge", "E31")] * 2
    _, turned = one.history(3, 0)
    assert (turned.piece, turned.reason, turned.across) == (1, "seam", 0)


def test_a_vertex_on_the_near_plane_makes_a_zero_area_piece():
    """The clipper keeps a vertex lying exactly on the near plane and adds the crossing at
    that very vertex: a second piece of zero area. The diagonal of the first piece then lies
    along the near plane: a clip edge (nothing lies beyond it), not a seam."""
    xy = np.array([[[2.0, 2.0], [22.0, 4.0], [6.0, 16.0]]])
    clip = clip_from_window(xy, [[0.0, 0.5, -0.5]], 1.0, W, H)  # v1 on near, v3 beyond it
    frame = tr.render(clip, W, H, trace=True)
    assert len(frame.trace.window) == 2
    counts = check_reasons(frame, clip)
    assert counts["seam"] == 0 and counts["zero_area"] > 0 and counts["clipped_away"] > 0
    first, second = frame.history(9, 5)
    assert (first.reason, first.edge, second.reason) == ("clipped_away", "near", "zero_area")
    assert "beyond the near clip edge by 4.2989 px" in str(frame.history(9, 5))
