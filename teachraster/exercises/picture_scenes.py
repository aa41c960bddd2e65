"""The small scenes of :mod:`.scenes`: ``fill``'s fan and one per exercise of 05–08.

Every scene's inputs and the package's picture are computed once (cached) from the package's
own functions (:func:`teachraster.rasterize`, :func:`teachraster.render`,
:func:`teachraster.mip_level`, :func:`teachraster.sample`, the block verdicts of
:mod:`.tile_blocks`); the student's picture calls the student's function for every pixel
(or block) the scene needs, on copies of the arguments.
"""

from __future__ import annotations

from dataclasses import replace
from functools import cache
from types import SimpleNamespace

import numpy as np

from ..core.fill import rasterize
from ..core.sample_patterns import sample_pattern
from ..core.triangle import Triangle
from ..pipeline.mip_pyramid import mipmap
from ..pipeline.render_triangles import Frame, render
from ..pipeline.scenes import get_scene
from ..pipeline.texture import checkerboard, sample
from ..pipeline.texture_filters import mip_level
from ..pipeline.visibility.zbuffer import passes_depth_test
from . import antialiasing as aa
from . import depth_precision as dp
from . import level_of_detail as lod
from . import texture_filtering as tf
from . import tile_blocks as tb
from .answers import as_coverage
from .cases import catalogue_coverage
from .coverage import edge_name, expected_coverage, explain_pixel, point
from .running import WrongAnswerType
from .scalars import num, vec
from .scenes import Scene, call


def _frozen(*arrays):
    for a in arrays:
        a.flags.writeable = False
    return arrays if len(arrays) > 1 else arrays[0]


# -- fill: a fan of 16 triangles ----------------------------------------------------------------
#: The catalogue case drawn for fill.
FILL_FAN = "fan_spokes_through_centres"
#: Codes of the fill picture: how many triangles cover a pixel.
COUNTS = (("not covered", "#ffffff"), ("covered once", "#2b7bba"), ("covered twice or more", "#ff9f1c"))  # fmt: skip


@cache
def fill_fan():
    """The fan (its shared edges through pixel centres), every other triangle wound the other
    way round (a fill handles both windings), and the package's coverage of each triangle."""
    fan = next(c for c in catalogue_coverage() if c.label == FILL_FAN)
    triangles = fan.triangles.copy()
    triangles[1::2] = triangles[1::2][:, [0, 2, 1]]
    label = f"{FILL_FAN}, every other triangle wound the other way"
    case = replace(fan, label=label, triangles=triangles)
    return case, _frozen(np.array([expected_coverage(case, xy) for xy in case.triangles]))


def fill_scene(fn) -> Scene:
    case, expected = fill_fan()
    w, h = case.size

    def run():
        images = []
        for xy in case.triangles:
            image = call(fn, lambda v: as_coverage(v, h, w), xy, w, h)
            images.append(image if image.shape == (h, w) else image.T)
        scene.parts = np.array(images)
        return np.minimum(scene.parts.sum(axis=0), 2).astype(float)

    def explain(got, row, col):
        return fill_pixel(case, expected, scene.parts, row, col)

    reference = np.minimum(expected.sum(axis=0), 2).astype(float)
    title = "a fan of 16 triangles, wound both ways: how many cover each pixel"
    scene = Scene(title, reference, run, explain, COUNTS)
    return scene


def fill_pixel(case, expected, got, i: int, j: int) -> str:
    """Why pixel (row i, column j) of the fan is covered as it is, and what yours did."""
    centre = np.array([j + 0.5, i + 0.5])
    want = np.flatnonzero(expected[:, i, j])
    head = f"centre {point(centre)}: "
    wrong = np.flatnonzero(expected[:, i, j] != got[:, i, j])
    if not len(wrong):
        which = f"triangle {want[0]}" if len(want) else "no triangle"
        return head + f"covered by {which}, in yours as in the package's"
    k = int(wrong[0])
    text, edge, _ = explain_pixel(case.triangles[k], centre, bool(expected[k, i, j]))
    where = f" (edge {edge_name(edge)})" if edge is not None else ""
    times = int(got[:, i, j].sum())
    return head + f"the rule covers it {len(want)} time(s), yours {times}. Triangle {k}{where}: {text}"  # fmt: skip


# -- the fan (coverage_fraction, resolve) -----------------------------------------------------
FAN_SIZE, FAN_SAMPLES = 20, 4


@cache
def fan():
    """Eight triangles around a sample position, and their 4-sample coverage.

    The centre is sample 0 of pixel (10, 10); the spokes run along the rows, the columns and
    the diagonals, so that many samples lie exactly on shared edges (the top-left rule
    decides them), every other rim vertex sits 1/1024 px off the grid (snapping decides) and
    every other triangle runs the other way round.
    """
    centre = np.array([10.375, 10.125])
    spokes = np.array([[8, 0], [6, 6], [0, 8], [-6, 6], [-8, 0], [-6, -6], [0, -8], [6, -6]])
    rim = centre + spokes + np.array([[0.0, 1 / 1024], [0.0, 0.0]] * 4)
    tris = np.array([[centre, rim[k], rim[(k + 1) % 8]] for k in range(8)])
    tris[1::2] = tris[1::2, ::-1]  # every other triangle counter-clockwise: both windings
    samples = sample_pattern(FAN_SAMPLES)
    cov = np.array([rasterize(Triangle(t), FAN_SIZE, FAN_SIZE, samples=samples).sample_coverage for t in tris])  # fmt: skip
    return _frozen(tris, cov)


def _window(xy, size):
    lo = np.clip(np.floor(xy.min(axis=0)).astype(int) - 1, 0, size)
    hi = np.clip(np.ceil(xy.max(axis=0)).astype(int) + 1, 0, size)
    return range(lo[1], hi[1]), range(lo[0], hi[0])


def coverage_scene(fn) -> Scene:
    tris, cov = fan()
    samples = sample_pattern(FAN_SAMPLES)
    reference = cov.mean(axis=3)  # (T, H, W): each triangle's fraction
    scene = Scene("a fan, fraction of 4 samples covered", reference.sum(axis=0), None, None,
                  value_name="fraction of the samples covered")  # fmt: skip

    def run():
        out = np.zeros_like(reference)
        for t, xy in enumerate(tris):
            rows, cols = _window(xy, FAN_SIZE)
            for i in rows:
                for j in cols:
                    out[t, i, j] = call(fn, aa.as_fraction, xy, (i, j), samples)
        scene.parts = out  # per triangle, for the explanations
        return out.sum(axis=0)

    cause = []  # the slip that gives every differing answer of the picture, found once

    def explain(got, row, col):
        for t, xy in enumerate(tris):
            expected, yours = reference[t, row, col], scene.parts[t, row, col]
            if not np.isclose(yours, expected):
                args = (np.array(xy), (row, col), np.array(samples))
                if not cause:
                    cause.append(_picture_slip(tris, samples, reference, scene.parts))
                words = aa.explain_coverage(args, expected, yours)
                return f"triangle {t + 1} of the fan: {words}{cause[0](args, expected, yours)}"
        return f"yours and the package's agree: {num(reference[:, row, col].sum())} covered"

    scene.run, scene.explain_at, scene.inputs = run, explain, _fan_inputs
    return scene


def _picture_slip(tris, samples, reference, parts, most: int = 60):
    """``words(args, expected, got)``: the one slip of 6.1's table (no combination) that gives
    every differing answer of the picture (at most ``most`` of them), as the check names it,
    or a pointer to the check (r64 06-3: a pixel's line named no cause). A slip that matches
    only this pixel is not named: few values are possible, and a coincidence would mislead."""
    where = np.argwhere(~np.isclose(parts, reference))[:most]
    singles = [m for m in aa.coverage_mistakes() if not m.parts and m.gives is not None]
    for m in singles:
        if all(_gives(m, (tris[t], (i, j), samples), parts[t, i, j]) for t, i, j in where):
            return lambda args, expected, got, m=m: ": " + m.say(args, expected, got)
    return lambda args, expected, got: "; the check's failures above name the cause"


def _gives(mistake, args, got) -> bool:
    value = mistake.gives(*(np.array(a) if isinstance(a, np.ndarray) else a for a in args))
    return value is not None and np.isclose(value, got)


def _fan_inputs(ax) -> str:
    """The fan's triangles over the pixel grid, with the sample points: coverage_fraction's
    inputs, none decided."""
    tris, _ = fan()
    points = sample_pattern(FAN_SAMPLES)
    grid = np.indices((FAN_SIZE, FAN_SIZE)).reshape(2, -1).T[:, ::-1]  # (col, row)
    at = (grid[:, None, :] + points[None]).reshape(-1, 2)
    ax.plot(*at.T, ".", color="#888888", ms=1.5)
    for xy in tris:
        ring = np.vstack([xy, xy[:1]])
        ax.plot(ring[:, 0], ring[:, 1], color="#2b7bba", linewidth=1)
    ax.set_xlim(0, FAN_SIZE)
    ax.set_ylim(FAN_SIZE, 0)
    ax.set_aspect("equal")
    return f"a fan of {len(tris)} triangles over {FAN_SIZE} × {FAN_SIZE} pixels, {FAN_SAMPLES} samples each (grey)"


@cache
def fan_colours():
    tris, cov = fan()
    ids = np.full(cov.shape[1:], -1)
    for t in range(len(tris)):
        ids[cov[t]] = t
    palette = np.array([[0.85, 0.3, 0.2], [0.95, 0.7, 0.2], [0.3, 0.65, 0.3], [0.2, 0.5, 0.8], [0.5, 0.35, 0.7], [0.2, 0.2, 0.25], [0.6, 0.8, 0.9], [0.9, 0.5, 0.6]])  # fmt: skip
    colours = np.where((ids >= 0)[..., None], palette[np.maximum(ids, 0)], np.nan)
    background = np.ones(3)
    resolved = Frame.resolve(SimpleNamespace(sample_triangle_id=ids), colours, background)
    return _frozen(ids, colours, background, resolved)


def resolve_scene(fn) -> Scene:
    ids, colours, background, reference = fan_colours()

    def run():
        out = np.empty_like(reference)
        for i in range(FAN_SIZE):
            for j in range(FAN_SIZE):
                out[i, j] = call(fn, aa.as_colour, colours[i, j], ids[i, j], background)
        return out

    cause = []  # r443 S2 (r432 S2): the slip that gives every differing pixel, found once

    def explain(got, row, col):
        args = (colours[row, col].copy(), ids[row, col].copy(), background.copy())
        if aa.same_colour(got[row, col], reference[row, col], args):
            return "yours and the package's agree"
        if not cause:
            cause.append(_resolve_slip(got))
        words = aa.explain_resolve(args, reference[row, col], got[row, col])
        return words + cause[0](args, reference[row, col], got[row, col])

    scene = Scene("a fan in colour, 4 samples resolved", reference, run, explain)
    scene.inputs = _sample_inputs
    return scene


def _resolve_slip(got, most: int = 60):
    """``words(args, expected, got)``: the one slip of 6.2's table that gives every differing
    pixel of the picture (at most ``most`` of them), as the check names it, or a pointer to
    the check (r432 S2: the pixel's line gave numbers only, where 6.1's names the cause)."""
    ids, colours, background, reference = fan_colours()
    differ = ~np.isclose(np.asarray(got, dtype=float), reference, atol=1e-6).all(axis=-1)
    where = np.argwhere(differ)[:most]
    for m in aa.RESOLVE_MISTAKES:
        if m.gives is None or m.parts or not len(where):
            continue
        if all(
            _gives_colour(m, (colours[i, j], ids[i, j], background), got[i, j]) for i, j in where
        ):
            return lambda args, expected, yours, m=m: m.say(args, expected, yours)
    return lambda args, expected, yours: "; the check's failures above name the cause"


def _gives_colour(mistake, args, got) -> bool:
    try:
        value = mistake.gives(*(np.array(a) for a in args))
    except (ValueError, TypeError, IndexError, ZeroDivisionError):
        return False
    return value is not None and bool(np.allclose(value, got, atol=1e-6, equal_nan=False))


def _sample_inputs(ax) -> str:
    """Every pixel's 4 samples before the resolve, as a 2 × 2 block of colours (white where
    no triangle covered a sample: the background): resolve's inputs."""
    ids, colours, background, _ = fan_colours()
    shown = np.where((ids >= 0)[..., None], np.nan_to_num(colours), background)  # (H, W, S, 3)
    h, w = ids.shape[:2]
    blocks = (
        shown[:, :, :4].reshape(h, w, 2, 2, 3).transpose(0, 2, 1, 3, 4).reshape(2 * h, 2 * w, 3)
    )
    ax.imshow(blocks, extent=(0, w, h, 0), interpolation="nearest")
    return "each pixel's 4 samples before the resolve (white: the background)"


# -- z-fighting (depth_to_unorm) --------------------------------------------------------------
DEPTH_BITS = 16


@cache
def two_planes():
    """Depths of two nearly coplanar triangles over a 32 × 16 window, and the winner codes."""
    xy = np.array([[-1.0, -1.0], [70.0, -1.0], [-1.0, 40.0]])
    za = rasterize(Triangle(xy, z=[0.7, 0.7 + 71 * 2e-6, 0.7 + 41 * 1e-6]), 32, 16).depth
    zb = rasterize(Triangle(xy, z=[0.70003, 0.70003 - 71 * 1e-6, 0.70003 - 41 * 2e-6]), 32, 16).depth  # fmt: skip
    stored = np.stack([_stored(za), _stored(zb)])
    return _frozen(za, zb, _winner(*stored), stored)


def _stored(z):
    return np.vectorize(lambda d: dp.stored(float(d), DEPTH_BITS))(z)


def _winner(stored_a, stored_b):
    """1 where A (drawn first) stays, 2 where B passes the test (strictly smaller)."""
    return np.where(passes_depth_test(stored_b, stored_a), 2.0, 1.0)


def depth_scene(fn) -> Scene:
    za, zb, reference, stored = two_planes()

    def run():
        a = np.vectorize(lambda d: call(fn, dp.as_count, float(d), DEPTH_BITS))(za)
        b = np.vectorize(lambda d: call(fn, dp.as_count, float(d), DEPTH_BITS))(zb)
        scene.parts = np.stack([a, b])
        return _winner(a, b)

    def explain(got, row, col):
        a, b = scene.parts[:, row, col]
        words = []
        for name, z, yours in (("A", za[row, col], a), ("B", zb[row, col], b)):
            if not dp.same_depth(yours, dp.stored(z, DEPTH_BITS), (float(z), DEPTH_BITS)):
                words.append(f"surface {name}: " + dp.explain_depth((float(z), DEPTH_BITS), dp.stored(z, DEPTH_BITS), yours))  # fmt: skip
        head = f"A (drawn first) stores {num(a, b)}, B {num(b, a)} in your buffer; B wins only with a strictly smaller value"  # fmt: skip
        return "; ".join([head, *words])

    categories = (("nothing", "#ffffff"), ("A stays", "#2b7bba"), ("B passes", "#ff9f1c"))
    title = "two nearly coplanar triangles, 16-bit depth"
    scene = Scene(title, reference, run, explain, categories, reference_parts=stored)
    return scene


# -- the textured floor (mip_level, bilinear, trilinear) --------------------------------------
FLOOR = (48, 40)  # width, height of the render (the rows of sky are cropped)
TILES = 3  # the texture repeats 3 times across the floor


@cache
def floor():
    """uv and its quad derivatives over the lesson's floor (uv scaled: the texture repeats)."""
    scene = get_scene("textured_floor")
    w, h = FLOOR
    frame = render(scene.clip(w / h), w, h, attrs=scene.mesh.corner("uv"), derivatives=True)
    rows = slice(np.flatnonzero(frame.coverage.any(axis=1))[0], h)  # the sky is left out
    return _frozen(*(a[rows] * TILES for a in (frame.attrs, frame.ddx, frame.ddy)))


@cache
def floor_texture(texels: int):
    texture = checkerboard(checks=4, texels=texels)
    return _frozen(texture, *mipmap(texture))


def _per_pixel(uv, value, reference):
    """``value(i, j)`` at every covered pixel of the floor; NaN elsewhere. An answer of
    another size than the package's (channels) is explained, never a crash."""
    covered = ~np.isnan(uv[..., 0])
    out = np.full(reference.shape, np.nan)
    want = reference.shape[2:]
    for i, j in np.argwhere(covered):
        v = np.asarray(value(i, j), dtype=float)
        if v.size != int(np.prod(want)):
            n = int(np.prod(want))
            raise WrongAnswerType(
                f"returned {v.size} value(s) at pixel ({i}, {j}); the texture has "
                f"{n} channel{'s' * (n != 1)}, so the answer is {n} value{'s' * (n != 1)}"
            )
        out[i, j] = v.reshape(want)
    return out


def level_scene(fn) -> Scene:
    uv, ddx, ddy = floor()
    size = (64, 64)
    reference = mip_level(ddx, ddy, size)

    def run():
        return _per_pixel(
            uv, lambda i, j: call(fn, aa.as_fraction, ddx[i, j], ddy[i, j], size), reference
        )

    def explain(got, row, col):
        if np.isnan(reference[row, col]):
            return "no floor here"
        args = (ddx[row, col].copy(), ddy[row, col].copy(), size)
        if np.isclose(got[row, col], reference[row, col]):
            return f"yours and the package's agree: λ = {num(reference[row, col])}"
        words = lod.explain_level(args, float(reference[row, col]), float(got[row, col]))
        return lod.hinted("mip_level", words, lod.HINTS)

    scene = Scene("λ over a floor, 64\u00a0×\u00a064 texture", reference, run, explain,
                  value_name="λ, the level of detail")  # fmt: skip
    scene.inputs = _uv_inputs
    return scene


def _uv_inputs(ax) -> str:
    """u over the floor (mod 1: where the texture repeats): the coordinate whose steps from
    pixel to pixel are mip_level's ddx and ddy."""
    uv, _, _ = floor()
    h, w = uv.shape[:2]
    ax.imshow(np.mod(uv[..., 0], 1.0), cmap="gray", vmin=0, vmax=1, extent=(0, w, h, 0),
              interpolation="nearest")  # fmt: skip
    return "the floor's u (mod 1); ddx and ddy are its steps from pixel to pixel"


def _texture_inputs(texels: int):
    def draw(ax) -> str:
        texture = floor_texture(texels)[0]
        ax.imshow(texture, cmap="gray", vmin=0, vmax=1, extent=(0, texels, texels, 0),
                  interpolation="nearest")  # fmt: skip
        # r418 FIG2: non-breaking spaces keep "8 × 8" on one line of the wrapped title
        return f"the {texels}\u00a0×\u00a0{texels} texture the floor repeats"

    return draw


def bilinear_scene(fn) -> Scene:
    uv, _, _ = floor()
    texture = floor_texture(8)[0]
    reference = sample(texture, uv, "bilinear", "repeat")

    def run():
        return _per_pixel(
            uv, lambda i, j: call(fn, tf.as_texel_value, texture, uv[i, j], "repeat"), reference
        )

    scene = Scene("a floor, 8\u00a0×\u00a08 texture, bilinear", reference, run, _texel_explainer(uv, texture, reference))  # fmt: skip
    scene.inputs = _texture_inputs(8)
    return scene


def _texel_explainer(uv, texture, reference, lam=None):
    def explain(got, row, col):
        if np.isnan(uv[row, col, 0]):
            return "no floor here"
        if tf.same_value(got[row, col], reference[row, col], None):
            return "yours and the package's agree"
        # the case's arguments first: in the check they stand in the case's label
        where = f"uv={vec(uv[row, col])}, wrap 'repeat'"
        if lam is None:
            args = (texture.copy(), uv[row, col].copy(), "repeat")
            words = tf.explain_bilinear(args, reference[row, col], got[row, col])
            return f"{where}, {words}"
        args = (
            tf.Pyramid(lv.copy() for lv in texture),
            uv[row, col].copy(),
            float(lam[row, col]),
            "repeat",
        )
        words = tf.explain_trilinear(args, reference[row, col], got[row, col])
        q, at = len(texture) - 1, float(lam[row, col])
        if not 0 <= at <= q:  # r286 S10: where λ leaves the pyramid, the likely cause asked
            words += f"; λ lies outside the pyramid [0, {q}] here: was it clamped first?"
        return f"{where}, λ={num(at)}, {words}"

    return explain


def trilinear_scene(fn) -> Scene:
    uv, ddx, ddy = floor()
    pyramid = tf.Pyramid(floor_texture(64)[1:])
    lam = mip_level(ddx, ddy, pyramid[0].shape)
    reference = sample(pyramid, uv, "trilinear", "repeat", lod=lam)

    def run():
        return _per_pixel(uv, lambda i, j: call(fn, tf.as_texel_value, pyramid, uv[i, j], float(lam[i, j]), "repeat"), reference)  # fmt: skip

    scene = Scene("a floor, 64\u00a0×\u00a064 texture, trilinear at the package's λ", reference, run, _texel_explainer(uv, pyramid, reference, lam))  # fmt: skip
    scene.inputs = _texture_inputs(64)
    return scene


# -- the tile walk (classify_block) -----------------------------------------------------------
TILE_IMAGE, TILE_SIZES = 48, (16, 4)
#: Each classic mistake shows; not symmetric about x = y (r94 D8-10: x0 and y0 swapped drew
#: the mirrored block's verdict, the same one, and the picture showed no difference)
TILE_TRIANGLE = np.array([[6.0, 6.0], [44.5, 18.5], [17.5, 45.5]])
#: Pixel codes of the walk: the deepest verdict each pixel got.
WALK = (
    ("rejected", "#ffffff"),
    ("accepted as a 16-block", "#1b7837"),
    ("accepted as a 4-block", "#7fbf7b"),
    ("tested: covered", "#2b7bba"),
    ("tested: not covered", "#c6dbef"),
)


def walk(classify):
    """Codes of the tile walk with ``classify(xy, x0, y0, size)`` called on grids (the image's
    16-blocks in one call, then each partial one's 4-blocks in one call), and its verdicts."""
    codes = np.zeros((TILE_IMAGE, TILE_IMAGE))
    verdicts = {}
    coverage = rasterize(Triangle(TILE_TRIANGLE), TILE_IMAGE, TILE_IMAGE).coverage
    big, small = TILE_SIZES
    for x0, y0, kind in _grid_walk(classify, 0, 0, TILE_IMAGE, big):
        verdicts[(x0, y0, big)] = kind
        if kind == "accepted":
            codes[y0 : y0 + big, x0 : x0 + big] = 1
        if kind != "partial":
            continue
        for x1, y1, kind in _grid_walk(classify, x0, y0, big, small):
            verdicts[(x1, y1, small)] = kind
            block = (slice(y1, y1 + small), slice(x1, x1 + small))
            if kind == "accepted":
                codes[block] = 2
            elif kind == "partial":
                codes[block] = np.where(coverage[block], 3, 4)
    return codes, verdicts


def _grid_walk(classify, x0, y0, side, size):
    """(x0, y0, verdict) of each ``size`` block of the ``side`` square at (x0, y0), from one
    call of ``classify`` on the grid of them."""
    yy, xx = np.mgrid[y0 : y0 + side : size, x0 : x0 + side : size]
    kinds = np.broadcast_to(np.asarray(classify(TILE_TRIANGLE.copy(), xx, yy, size)), xx.shape)
    return [(int(x), int(y), str(k)) for x, y, k in zip(xx.ravel(), yy.ravel(), kinds.ravel(), strict=True)]  # fmt: skip


def tile_scene(fn) -> Scene:
    reference, truth = walk(tb.expected_block)

    def run():
        codes, scene.parts = walk(lambda *a: tb.call_block(lambda *b: call(fn, tb.as_kind, *b), a))
        return codes

    def explain(got, row, col):
        for size in TILE_SIZES:
            key = (col // size * size, row // size * size, size)
            if key in scene.parts and scene.parts[key] != truth.get(key, scene.parts[key]):
                words = tb.explain_block((TILE_TRIANGLE.copy(), *key), truth[key], scene.parts[key])  # fmt: skip
                # r94 D8-3: the first try's caption gave the block's extreme centres; r198 C.3:
                # the block named once, as x0, y0 (the pixel is (row, col): no "(36, 20)" beside it)
                return lod.hinted("classify_block", words, tb.BLOCK_HINTS) + _pixel_why(got, row, col)  # fmt: skip
            if key in truth and key not in scene.parts:
                return f"the package visits the block x0={key[0]}, y0={key[1]}, size={size}, yours does not: its parent's verdict differs"  # fmt: skip
        return f"yours and the package's agree: {WALK[int(reference[row, col])][0]}"

    # r94 D8-11: "the package's: a tile walk: blocks of 16, then 4, then pixels" took three
    # lines over its panel
    scene = Scene("tile walk: blocks 16, 4, 1", reference, run, explain, WALK,
                  coverage_of=walk_coverage)  # fmt: skip
    return scene


def _pixel_why(got, row: int, col: int) -> str:
    """Where the pixel is filled by one walk and not the other: which and why (r173 D1)."""
    ours = bool(walk_coverage(walk(tb.expected_block)[0])[row, col])
    if got is None:
        return ""
    if bool(walk_coverage(np.asarray(got))[row, col]) == ours:  # r376 F6: the reason said too
        return (f"; both walks {'fill' if ours else 'leave out'} this pixel: a partial block's "
                "pixels are each tested, so here only the walk's work differs, not the picture")  # fmt: skip
    who = "the package fills this pixel, yours does not" if ours else "yours fills this pixel, the package does not"  # fmt: skip
    return f"; {who}: {tb.pixel_words(TILE_TRIANGLE.copy(), row, col)}"


def walk_coverage(codes: np.ndarray) -> np.ndarray:
    """The pixels a walk's codes fill: accepted in a block, or tested and covered (r149 E1)."""
    return np.isin(codes, (1, 2, 3))
