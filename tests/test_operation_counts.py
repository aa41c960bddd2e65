"""The operation-count cost model of lesson 06 and the meshes that crack."""

import numpy as np
import pytest

import teachraster as tr
from teachraster.study import operation_counts as ops


def test_interpolation_counts_follow_the_formulas():
    affine, persp = ops.interpolation_count("affine"), ops.interpolation_count("perspective")
    assert (affine.divides, persp.divides) == (0, 1)
    for n in (2, 4, 8, 16, 32):
        sub = ops.interpolation_count(f"subdivided N={n}")
        assert sub.divides == 1 / n and affine.additions < sub.additions
        assert ops.cycles(affine) < ops.cycles(sub) < ops.cycles(persp)
    with pytest.raises(ValueError):
        ops.interpolation_count("cubic")


def test_edge_counts_and_bits():
    direct, inc = ops.edge_count("fixed8 direct"), ops.edge_count("fixed8 incremental")
    assert (direct.multiplies, direct.additions, inc.multiplies, inc.additions) == (6, 9, 0, 3)
    assert ops.edge_count("float32 direct").bits == 24 < ops.edge_bits_needed(512, 1e6)
    assert ops.edge_count("fixed8 direct").bits >= ops.edge_bits_needed(2048, 1e6)
    assert ops.edge_bits_needed(16, 1_000_000) == 28  # the position dominates
    with pytest.raises(ValueError):
        ops.edge_count("float16 direct")


def test_fill_counts_scale_with_the_box_and_the_rows():
    hp, sp = ops.fill_count("halfplane 64²"), ops.fill_count("span+trace 64²")
    tri = tr.rasterize(ops.bench.fill_triangle(64), 64, 64, trace=True).trace
    assert hp.additions == 6 * tri.bbox.size and hp.divides == 0
    assert sp.divides == 1 + 2 * (tri.bbox.row1 - tri.bbox.row0)
    assert ops.cycles(sp) < ops.cycles(hp)


def test_with_counts_adds_columns_to_every_row():
    rows = [{"group": "interpolation", "variant": "affine"},
            {"group": "depth", "variant": "window unorm16"}]  # fmt: skip
    out = ops.with_counts(rows)
    assert out[0]["cycles"] == 1 and out[1]["bits"] == 16 and "cycles" not in rows[0]
    assert ops.with_counts(rows, {"divides": 0, "multiplies": 0, "additions": 2})[0]["cycles"] == 2


def test_tie_mesh_is_watertight_and_on_pixel_centres():
    mesh = ops.tie_mesh(24, cells=3)
    assert np.all((mesh - 0.5) % 1 == 0)
    counts = sum(tr.rasterize(tr.Triangle(t), 24, 24).coverage.astype(int) for t in mesh)
    assert counts.max() == 1


def test_only_an_inconsistent_tie_rule_cracks_the_mesh():
    mesh = ops.tie_mesh(24, cells=3)
    good = ops.crack_counts(mesh, 24, 24, "top-left")
    assert good["gaps"] == good["double_hits"] == 0
    # the rule of ops equals the package's own coverage, triangle by triangle
    for t in mesh:
        assert np.array_equal(ops.rule_coverage(t, 24, 24, "top-left"),
                              tr.rasterize(tr.Triangle(t), 24, 24).coverage)  # fmt: skip
    assert ops.crack_counts(mesh, 24, 24, "E >= 0")["double_hits"] > 0
    assert ops.crack_counts(mesh, 24, 24, "E > 0")["gaps"] > 0
    with pytest.raises(ValueError, match="rule"):
        ops.rule_coverage(mesh[0], 4, 4, "E != 0")


def test_cracks_are_counted_inside_the_outline_only():
    # The outline is decided by the neighbouring mesh: E > 0 leaves exactly the shared-edge
    # centres open that E >= 0 draws twice, and neither count includes the outline.
    mesh = ops.tie_mesh(24, cells=3)
    ge, gt = ops.crack_counts(mesh, 24, 24, "E >= 0"), ops.crack_counts(mesh, 24, 24, "E > 0")
    assert ge["double_hits"] == gt["gaps"] > 0 and ge["gaps"] == gt["double_hits"] == 0
    outline = ops.outline_centres(mesh, 24, 24)
    assert np.array_equal(outline, ge["outline"])
    # the tie mesh is a square whose corners are on centres: its outline is the square's border
    lo, hi = int(mesh.min()), int(mesh.max())
    side = hi - lo + 1
    assert outline.sum() == 4 * (side - 1)
    assert (gt["counts"][outline] == 0).all()  # E > 0 leaves the outline to the neighbour


def test_depth_rows_carry_the_bits_they_store():
    rows = [{"group": "depth", "variant": f"window {f}"} for f in ops.DEPTH_STORED_BITS]
    stored = {r["variant"].split()[1]: r["stored_bits"] for r in ops.with_counts(rows)}
    assert stored == {"float64": 64, "float32": 32, "unorm24": 24, "unorm16": 16}
    precision = {r["variant"].split()[1]: r["bits"] for r in ops.with_counts(rows)}
    assert precision["float32"] == precision["unorm24"] == 24  # the same step near depth 1
