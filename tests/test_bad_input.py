"""Bad input fails early with ValueError/TypeError whose message names the offending argument."""

import numpy as np
import pytest

import teachraster as tr

GOOD_XY = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]


def tri(**kw):
    return tr.Triangle(kw.pop("xy", GOOD_XY), **kw)


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        # positions
        ({"xy": [[0, 0], [np.nan, 0], [0, 4]]}, ValueError, r"xy.*NaN"),
        ({"xy": [[0, 0], [np.inf, 0], [0, 4]]}, ValueError, r"xy.*infinity"),
        ({"xy": [[0, 0], [4, 0], [0, -np.inf]]}, ValueError, r"xy"),
        ({"xy": [[0, 0, 0], [4, 0, 0], [0, 4, 0]]}, ValueError, r"xy must have shape \(3, 2\)"),
        ({"xy": [[0, 0], [4, 0]]}, ValueError, r"xy.*shape"),
        ({"xy": [[0, 0], [4, 0], [0, 4], [4, 4]]}, ValueError, r"xy.*shape"),
        ({"xy": [0, 0, 4, 0, 0, 4]}, ValueError, r"xy.*shape"),
        ({"xy": [[0, 0], [4], [0, 4]]}, TypeError, r"xy"),
        ({"xy": [["a", "b"], [4, 0], [0, 4]]}, TypeError, r"xy must be numeric"),
        ({"xy": None}, ValueError, r"xy.*shape"),
        # w
        ({"w": [1.0, 1.0]}, ValueError, r"w must have shape \(3,?\)"),
        ({"w": [[1.0, 1.0, 1.0]]}, ValueError, r"\bw\b.*shape"),
        ({"w": [1.0, np.nan, 1.0]}, ValueError, r"\bw\b.*NaN"),
        ({"w": [1.0, np.inf, 1.0]}, ValueError, r"\bw\b"),
        ({"w": [1.0, 0.0, 1.0]}, ValueError, r"w must be > 0.*clip.*near plane"),
        ({"w": [1.0, 2.0, -0.5]}, ValueError, r"w must be > 0.*clip.*near plane"),
        ({"w": "abc"}, TypeError, r"\bw\b"),
        # z
        ({"z": [0.5, 0.5]}, ValueError, r"z must have shape"),
        ({"z": [0.5, 1.5, 0.5]}, ValueError, r"\bz\b.*\[0, 1\]"),
        ({"z": [-0.01, 0.5, 0.5]}, ValueError, r"\bz\b.*\[0, 1\]"),
        ({"z": [0.5, np.nan, 0.5]}, ValueError, r"\bz\b.*NaN"),
        ({"z": ["near", "far", "mid"]}, TypeError, r"\bz\b"),
        # attrs
        ({"attrs": {"u": [1.0, 2.0]}}, ValueError, r"attrs\['u'\].*shape"),
        ({"attrs": {"u": [1.0, 2.0, 3.0, 4.0]}}, ValueError, r"attrs\['u'\].*shape"),
        ({"attrs": {"rgb": np.zeros((2, 3))}}, ValueError, r"attrs\['rgb'\].*shape"),
        ({"attrs": {"rgb": np.zeros((3, 2, 2))}}, ValueError, r"attrs\['rgb'\].*shape"),
        ({"attrs": {"u": 1.0}}, ValueError, r"attrs\['u'\].*shape"),
        ({"attrs": {"u": ["a", "b", "c"]}}, TypeError, r"attrs\['u'\].*numeric"),
        ({"attrs": {"u": [1.0, np.nan, 3.0]}}, ValueError, r"attrs\['u'\].*NaN"),
        ({"attrs": {"u": [1.0, np.inf, 3.0]}}, ValueError, r"attrs\['u'\]"),
        ({"attrs": {1: [1.0, 2.0, 3.0]}}, TypeError, r"attrs.*names must be strings"),
        ({"attrs": [[1.0, 2.0, 3.0]]}, TypeError, r"attrs must be a mapping"),
    ],
)
def test_triangle_rejects_bad_input_naming_the_argument(kwargs, error, match):
    """tr.Triangle validates every argument and names it in the message."""
    with pytest.raises(error, match=match):
        tri(**kwargs)


def test_triangle_accepts_good_input_and_freezes_it():
    """Valid input is converted to float64 arrays that cannot be modified afterwards."""
    t = tri(w=[1, 2, 3], z=[0, 0.5, 1], attrs={"u": [1, 2, 3], "rgb": np.eye(3)})
    assert t.xy.dtype == t.w.dtype == t.z.dtype == t.attrs["u"].dtype == np.float64
    with pytest.raises(ValueError):
        t.xy[0, 0] = 99.0
    with pytest.raises(ValueError):
        t.attrs["rgb"][0, 0] = 99.0
    np.testing.assert_array_equal(tri().w, [1.0, 1.0, 1.0])  # default: no perspective
    assert tri(attrs=None).attrs == {}


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"width": 0}, ValueError, r"width must be positive"),
        ({"width": -3}, ValueError, r"width"),
        ({"height": 0}, ValueError, r"height must be positive"),
        ({"height": -1}, ValueError, r"height"),
        ({"width": 4.0}, TypeError, r"width must be an int"),
        ({"height": 4.5}, TypeError, r"height must be an int"),
        ({"width": True}, TypeError, r"width"),
        ({"height": False}, TypeError, r"height"),
        ({"width": "4"}, TypeError, r"width"),
        ({"height": None}, TypeError, r"height"),
        ({"method": "scanline"}, ValueError, r"method must be one of"),
        ({"method": "Span"}, ValueError, r"method"),
        ({"method": None}, ValueError, r"method"),
        ({"interpolation": "linear"}, ValueError, r"interpolation must be one of"),
        ({"interpolation": "smooth"}, ValueError, r"interpolation"),
        ({"cull": "both"}, ValueError, r"cull must be one of"),
        ({"cull": "Back"}, ValueError, r"cull"),
        ({"cull": True}, ValueError, r"cull"),
        ({"subpixel_bits": -1}, ValueError, r"subpixel_bits"),
        ({"subpixel_bits": 17}, ValueError, r"subpixel_bits"),
        ({"subpixel_bits": 8.0}, TypeError, r"subpixel_bits"),
        ({"subpixel_bits": True}, TypeError, r"subpixel_bits"),
        ({"subpixel_bits": "8"}, TypeError, r"subpixel_bits"),
    ],
)
def test_rasterize_rejects_bad_arguments_naming_them(kwargs, error, match):
    """tr.rasterize validates size, method, interpolation, cull and subpixel_bits."""
    args = {"width": 4, "height": 4, **kwargs}
    width, height = args.pop("width"), args.pop("height")
    with pytest.raises(error, match=match):
        tr.rasterize(tri(), width, height, **args)


@pytest.mark.parametrize("bad", [GOOD_XY, np.array(GOOD_XY), None, {"xy": GOOD_XY}])
def test_rasterize_needs_a_triangle(bad):
    """Passing positions (or anything else) instead of a tr.Triangle is a TypeError naming tri."""
    with pytest.raises(TypeError, match=r"tri must be a teachraster\.Triangle"):
        tr.rasterize(bad, 4, 4)


def test_rasterize_accepts_numpy_integer_sizes_and_valid_choices():
    """The checks are not too strict: numpy ints, every documented choice, bits 0..16, None."""
    for method in ("halfplane", "span"):
        for interpolation in ("perspective", "affine"):
            for cull in (None, "back", "front"):
                fill = tr.rasterize(
                    tri(), np.int64(4), np.int32(3), method=method,
                    interpolation=interpolation, cull=cull,
                )  # fmt: skip
                assert fill.coverage.shape == (3, 4)
    for bits in (0, 16, np.int64(4), None):
        tr.rasterize(tri(), 4, 4, subpixel_bits=bits)


def test_coordinates_too_large_for_the_snapping_grid_name_xy():
    """Coordinates that overflow the exact int64 grid raise ValueError mentioning xy."""
    with pytest.raises(ValueError, match="xy"):
        tr.rasterize(tri(xy=[[1e9, 0], [0, 1e9], [0, 0]]), 4, 4)
    with pytest.raises(ValueError, match="xy"):
        tr.rasterize(tri(xy=[[-1e9, 0], [0, 1], [1, 0]]), 4, 4, method="span")
    with pytest.raises(ValueError, match="xy"):
        tr.rasterize(tri(xy=[[1e7, 0], [0, 1], [1, 0]]), 4, 4, subpixel_bits=16)


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda: tr.barycentric([[0, 0], [1, 0]], [[0, 0]]), ValueError, r"xy.*shape"),
        (lambda: tr.barycentric(GOOD_XY, [[0, 0, 0]]), ValueError, r"points"),
        (lambda: tr.barycentric([[0, 0], [1, 1], [2, 2]], [[0, 0]]), ValueError, r"xy.*zero-area"),
        (lambda: tr.barycentric([[0, np.nan], [1, 0], [0, 1]], [[0, 0]]), ValueError, r"xy"),
        (lambda: tr.plane_equation(GOOD_XY, [1.0, 2.0]), ValueError, r"\bf\b.*shape"),
        (lambda: tr.plane_equation(GOOD_XY, [1.0, np.nan, 2.0]), ValueError, r"\bf\b"),
        (lambda: tr.plane_equation([[0, 0], [1, 1], [2, 2]], [1, 2, 3]), ValueError, r"xy"),
        (lambda: tr.setup_matrix([[0, 0], [1, 1]]), ValueError, r"xy.*shape"),
        (lambda: tr.setup_matrix([[5, 5]] * 3), ValueError, r"xy.*zero-area"),
        (lambda: tr.attribute_plane(GOOD_XY, [1.0, 2.0, 3.0, 4.0]), ValueError, r"\bf\b"),
    ],
)
def test_helper_functions_reject_bad_input(call, error, match):
    """barycentric, plane_equation, setup_matrix and attribute_plane name what is wrong."""
    with pytest.raises(error, match=match):
        call()
