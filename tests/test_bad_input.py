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


# -- issue 9: values numpy would mangle or report in its own words ----------------------------------
@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"xy": [[0, 0], [4j, 0], [0, 4]]}, TypeError, r"xy must be numeric.*complex"),
        ({"xy": np.array(GOOD_XY, dtype=complex)}, TypeError, r"xy.*complex"),
        ({"xy": b"\x00\x01\x02"}, TypeError, r"xy.*bytes"),
        ({"xy": "0 0 4 0 0 4"}, TypeError, r"xy.*str"),
        ({"xy": np.array([["0", "0"], ["4", "0"], ["0", "4"]])}, TypeError, r"xy.*strings"),
        ({"xy": {"a": 1}}, TypeError, r"xy.*dict"),
        ({"xy": {1, 2, 3}}, TypeError, r"xy.*set"),
        ({"xy": [[0, 0], [None, 0], [0, 4]]}, TypeError, r"xy"),
        ({"xy": [[0, 0], [[4], 0], [0, 4]]}, TypeError, r"xy.*ragged"),
        ({"xy": [[0, 0], [10**400, 0], [0, 4]]}, ValueError, r"xy.*too large for a float"),
        ({"xy": [[0, 0], [-(10**400), 0], [0, 4]]}, ValueError, r"xy.*too large"),
        ({"w": [1, 2 + 0j, 3]}, TypeError, r"\bw\b.*complex"),
        ({"w": np.array([1, 2, 3], dtype=np.complex64)}, TypeError, r"\bw\b.*complex"),
        ({"w": [1, 10**400, 3]}, ValueError, r"\bw\b.*too large"),
        ({"w": b"abc"}, TypeError, r"\bw\b"),
        ({"z": [0.5, 0.5j, 0.5]}, TypeError, r"\bz\b.*complex"),
        ({"attrs": {"u": [1, 2j, 3]}}, TypeError, r"attrs\['u'\].*complex"),
        ({"attrs": {"u": [[1, 2], [3], [4, 5]]}}, TypeError, r"attrs\['u'\].*ragged"),
        ({"attrs": {"u": {"a": 1}}}, TypeError, r"attrs\['u'\].*dict"),
        ({"attrs": {"u": b"abc"}}, TypeError, r"attrs\['u'\]"),
        ({"attrs": {"u": [1, 10**400, 3]}}, ValueError, r"attrs\['u'\].*too large"),
    ],
)
def test_triangle_rejects_values_numpy_would_mangle(kwargs, error, match):
    """Complex values are refused (not silently cast), strings/bytes/mappings/ragged lists and
    integers beyond the float range get an error naming the argument, not a raw numpy one."""
    with pytest.raises(error, match=match):
        tri(**kwargs)


def test_numpy_integer_scalars_act_as_python_ints():
    """np.int8(7) sub-pixel bits used to overflow inside int8 (2**(bits + 1)); every integer
    argument is now a Python int at the boundary, so numpy scalars give identical results."""
    t = tr.Triangle([[0.3, 0.2], [9.7, 1.1], [2.2, 7.9]], w=[1, 2, 3], attrs={"u": [0, 1, 2]})
    want = tr.rasterize(t, 10, 9, interpolation="subdivided", subdivision=3, subpixel_bits=7)
    got = tr.rasterize(t, np.uint8(10), np.int16(9), interpolation="subdivided",
                       subdivision=np.int8(3), subpixel_bits=np.int8(7), max_pixels=np.int32(90))  # fmt: skip
    np.testing.assert_array_equal(got.coverage, want.coverage)
    np.testing.assert_array_equal(got.attrs["u"], want.attrs["u"])
    np.testing.assert_array_equal(tr.snap(t.xy, np.int8(7)), tr.snap(t.xy, 7))
    from teachraster.core.snapping import units_per_pixel

    assert units_per_pixel(np.int8(7)) == 256 and type(units_per_pixel(np.int8(7))) is int
    clip = [[[-1, -1, 0, 1], [1, -1, 0, 2], [-1, 1, 0, 1]]]
    a = tr.render(clip, 8, 6, attrs=[[0, 1, 2]], subpixel_bits=7)
    b = tr.render(clip, np.uint8(8), np.int64(6), attrs=[[0, 1, 2]], subpixel_bits=np.int8(7))
    np.testing.assert_array_equal(a.triangle_id, b.triangle_id)
    np.testing.assert_array_equal(a.attrs, b.attrs)


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"subdivision": 10**30}, ValueError, r"subdivision is too large"),
        ({"width": 10**20}, ValueError, r"^width is too large"),
        ({"height": -(10**20)}, ValueError, r"^height"),
        ({"trace": "no"}, TypeError, r"trace must be True or False"),
        ({"trace": 1}, TypeError, r"trace"),
        ({"max_pixels": 0}, ValueError, r"max_pixels"),
        ({"max_pixels": "big"}, TypeError, r"max_pixels"),
        ({"max_pixels": 15}, ValueError, r"width x height = 4 x 4 = 16 pixels.*max_pixels = 15"),
        ({"method": {"span": 1}}, ValueError, r"method"),
    ],
)
def test_rasterize_rejects_huge_and_non_bool_arguments(kwargs, error, match):
    """Integers beyond a C long name the argument they were given for; trace must be a bool."""
    test_rasterize_rejects_bad_arguments_naming_them(kwargs, error, match)


CLIP = [[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]]


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"clip": [[[0, 0, 0, 1], [1, 0, 0, 1]], [[0, 0, 0, 1]] * 3]}, TypeError, r"clip.*ragged"),
        ({"clip": np.zeros((1, 3, 4), dtype=complex)}, TypeError, r"clip.*complex"),
        ({"clip": "triangles"}, TypeError, r"clip"),
        ({"clip": b"\x00" * 12}, TypeError, r"clip.*bytes"),
        ({"clip": {"a": CLIP}}, TypeError, r"clip.*dict"),
        ({"clip": [[[0, 0, 0, 1], [1, 0, 0, 1], [0, 10**400, 0, 1]]]}, ValueError, r"clip.*large"),
        (
            {"clip": np.zeros((5, 0, 4))},
            ValueError,
            r"clip must have shape \(k, 3, 4\), got \(5, 0, 4\)",
        ),
        ({"clip": np.zeros((2, 3, 3))}, ValueError, r"clip must have shape"),
        ({"clip": [[[0, 0, 0, np.nan]] * 3]}, ValueError, r"clip.*NaN"),
        ({"attrs": [[1, 2j, 3]]}, TypeError, r"attrs.*complex"),
        ({"attrs": [[1, 2], [3]]}, TypeError, r"attrs.*ragged"),
        ({"attrs": {"u": [1, 2, 3]}}, TypeError, r"attrs.*dict"),
        ({"attrs": [[1, 10**400, 3]]}, ValueError, r"attrs.*too large"),
        ({"attrs": [[1, 2]]}, ValueError, r"attrs must have shape \(1, 3, k\)"),
        ({"depth_test": "no"}, TypeError, r"depth_test must be True or False"),
        ({"depth_test": 0}, TypeError, r"depth_test"),
        ({"trace": "yes"}, TypeError, r"trace must be True or False"),
        ({"force": {"clipping": True}}, TypeError, r"force must be"),
        ({"force": np.array(["all"])}, TypeError, r"force must be"),
        ({"force": ["clipping", 3]}, TypeError, r"force must be"),
        ({"force": "everything"}, ValueError, r"force"),
        ({"width": 10**20}, ValueError, r"^width is too large"),
        ({"subpixel_bits": 10**30}, ValueError, r"^subpixel_bits is too large"),
        ({"max_pixels": 15}, ValueError, r"max_pixels = 15"),
        ({"cull": ["back"]}, ValueError, r"cull"),
    ],
)
def test_render_rejects_bad_input_naming_the_argument(kwargs, error, match):
    """tr.render: every argument checked in teachraster.pipeline.inputs, named in the message."""
    args = {"clip": CLIP, "width": 4, "height": 4, **kwargs}
    clip, width, height = args.pop("clip"), args.pop("width"), args.pop("height")
    with pytest.raises(error, match=match):
        tr.render(clip, width, height, **args)


def test_render_accepts_every_spelling_of_an_empty_scene():
    """[] and (0, 3, 4) are an empty scene; max_pixels at exactly the size is allowed."""
    for empty in ([], np.zeros((0, 3, 4)), np.zeros(0, dtype=np.int8)):
        frame = tr.render(empty, 4, 4, max_pixels=16)
        assert (frame.triangle_id == -1).all()
    assert tr.render(CLIP, 4, 4, force=("clipping", "perspective")).coverage.any()


@pytest.mark.parametrize(
    "call",
    [
        lambda: tr.rasterize(tri(), 100_000, 100_000),
        lambda: tr.render(CLIP, 100_000, 100_000),
        lambda: tr.render(tr.get_scene("cube"), None, 100_000, 100_000),
        lambda: tr.render(CLIP, 20_000, 20_000, max_pixels=10**8),
    ],
)
def test_huge_images_fail_at_once_before_allocating(call):
    """More than max_pixels (2**28 unless raised) is a ValueError naming width and height and
    the memory it would take, raised before anything image-sized is allocated."""
    import tracemalloc

    tracemalloc.start()
    try:
        with pytest.raises(ValueError, match=r"width x height = .* pixels .*GiB.*max_pixels=") as e:
            call()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 2**20, f"{peak} bytes allocated before the error"
    assert "max_pixels = " in str(e.value)


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"depth_test": "no"}, TypeError, r"depth_test"),
        ({"force": {"depth_test": 1}}, TypeError, r"force"),
        ({"texture_filter": "tricubic"}, ValueError, r"texture_filter"),
        ({"width": np.float64(64)}, TypeError, r"width"),
        ({"max_pixels": 100}, ValueError, r"max_pixels = 100"),
    ],
)
def test_render_scene_rejects_bad_input_naming_the_argument(kwargs, error, match):
    """tr.render(scene, ...) checks its own arguments and passes max_pixels on."""
    args = {"width": 16, "height": 12, **kwargs}
    with pytest.raises(error, match=match):
        tr.render(tr.get_scene("textured_floor"), None, **args)
    frame = tr.render(tr.get_scene("textured_floor"), None, np.int8(16), np.uint8(12))
    assert frame.image.shape == (12, 16, 3)


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda: tr.painter([[[0, 0, 0, 1]] * 2], 4, 4), ValueError, r"clip must have shape"),
        (lambda: tr.painter(CLIP, 4, 4, attrs=[[1j, 0, 0]]), TypeError, r"attrs.*complex"),
        (lambda: tr.painter(CLIP, 4, 4, key=["max"]), ValueError, r"key"),
        (lambda: tr.to_window([[0, 0, 0]], 4, 4), ValueError, r"clip must have shape \(\.\.\., 4\)"),
        (lambda: tr.to_window([[0, 0, 0, 1]], 4.0, 4), TypeError, r"width"),
        (lambda: tr.snap("1 2"), TypeError, r"xy"),
        (lambda: tr.snap([[1, 2]], np.float32(8)), TypeError, r"subpixel_bits"),
        (lambda: tr.texel_error([[0, 0]], [[0, 0]], (8.5, 4)), ValueError, r"shape"),
        (lambda: tr.sample(np.ones((2, 2), dtype=complex), [[0, 0]]), ValueError, r"texture"),
        (lambda: tr.sample(np.ones((2, 2)), [[0, 1j]]), TypeError, r"\buv\b"),
        (lambda: tr.Mesh(np.zeros((3, 3)), [[0, 1, 1e30]]), TypeError, r"triangles"),
        (lambda: tr.Mesh(np.zeros((3, 3)), [[0, 1, 2]], {"u": [[1], [2, 3], [4]]}), TypeError,
         r"attrs\['u'\]"),
    ],
)  # fmt: skip
def test_other_entry_points_reject_bad_input(call, error, match):
    """painter, to_window, snap, texel_error, sample and Mesh name what is wrong."""
    with pytest.raises(error, match=match):
        call()


def test_snap_near_the_float_maximum_needs_no_overflow():
    """Doubles beyond 2**(52 - bits) are already on the grid: kept, no overflow warning."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = tr.snap([[1.7e308, -1.7e308], [0.3, 2.0**60 + 2**8]], 8)
    np.testing.assert_array_equal(out, [[1.7e308, -1.7e308], [0.30078125, 2.0**60 + 2**8]])


# -- OBJ files ---------------------------------------------------------------------------------
SQUARE_OBJ = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"


@pytest.mark.parametrize("how", ["str", "bytes", "bytesio", "stringio", "path", "text_file"])
def test_obj_byte_order_mark_is_skipped(tmp_path, how):
    """A UTF-8 byte-order mark (Windows editors write one) is skipped however the file comes."""
    import io

    raw = b"\xef\xbb\xbf" + SQUARE_OBJ.encode()
    path = tmp_path / "bom.obj"
    path.write_bytes(raw)
    source = {
        "str": raw.decode("utf-8"),
        "bytes": raw,
        "bytesio": io.BytesIO(raw),
        "stringio": io.StringIO(raw.decode("utf-8")),
        "path": path,
        "text_file": None,
    }[how]
    if how == "text_file":
        with open(path, encoding="utf-8") as fh:  # not utf-8-sig: the mark reaches read_obj
            mesh = tr.read_obj(fh)
    else:
        mesh = tr.read_obj(source)
    assert mesh.triangles.tolist() == [[0, 1, 2], [0, 2, 3]]


def test_obj_non_utf8_bytes_in_a_comment_are_tolerated_elsewhere_reported(tmp_path):
    """Latin-1 bytes in a comment (an author's name) are harmless; in a statement they are an
    ObjError with the line number."""
    good = b"# made by Jos\xe9\n" + SQUARE_OBJ.encode()
    path = tmp_path / "latin1.obj"
    path.write_bytes(good)
    for source in (good, path):
        assert len(tr.read_obj(source).triangles) == 2
    bad = SQUARE_OBJ.encode().replace(b"v 1 1 0", b"v 1 1 0\xe9")
    with pytest.raises(tr.ObjError, match=r"^line 3: byte 0xe9 is not UTF-8"):
        tr.read_obj(bad)


@pytest.mark.parametrize("word", ["1_0", "+1", "\u0661", "\uff11", "1.0", "0x1", "1e0", "--1"])
def test_obj_indices_are_exactly_an_optional_minus_and_ascii_digits(word):
    """int() would take "1_0", "+1" and non-ASCII digits; OBJ indices are plain -?[0-9]+."""
    text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf " + word + " 2 3\n"
    with pytest.raises(tr.ObjError, match=r"^line 4: bad vertex index"):
        tr.read_obj(text)
    text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/" + word + " 2/1 3/1\n"
    with pytest.raises(tr.ObjError, match=r"^line 5: bad texture coordinate index"):
        tr.read_obj(text)


@pytest.mark.parametrize("word", ["1_0", "\u0661", "0x1"])
def test_obj_numbers_are_ascii(word):
    """float() also takes "1_0" and non-ASCII digits; OBJ numbers are ASCII decimals."""
    with pytest.raises(tr.ObjError, match=r"^line 2: bad number"):
        tr.read_obj("v 0 0 0\nv 1 " + word + " 0\n")
    mesh = tr.read_obj("v 0 0 0\nv +1.5e0 -.5 2.\nv 1 1 1\nf 1 2 -1\n")
    assert mesh.positions[1].tolist() == [1.5, -0.5, 2.0]


def test_numpy_integer_steps_and_plot_sizes():
    """A trace step given as np.int8 on a trace longer than 127 steps (k % n used to overflow
    inside int8); a 255-pixel grid given as np.uint8 (width + 1 used to wrap to 0)."""
    fill = tr.rasterize(tri(xy=[[0, 0], [20, 0], [0, 20]]), 20, 20, trace=True)
    assert len(fill.trace) > 127
    assert fill.trace.step(np.int8(100)) == fill.trace.step(100)
    with pytest.raises(TypeError, match=r"\bk\b"):
        fill.trace.step(1.0)
    import argparse

    from teachraster.cli.arguments import parse_size

    assert parse_size("16x12") == (16, 12)
    for bad in ("1_6x16", "+16x16", "\u0661\u0666x16"):
        with pytest.raises(argparse.ArgumentTypeError):
            parse_size(bad)
    plt = pytest.importorskip("matplotlib.pyplot")
    from teachraster.plotting import plot_pixel_grid

    fig, ax = plt.subplots()
    try:
        grid = plot_pixel_grid(ax, np.uint8(255), np.uint8(2), ticks=np.int8(4))
        assert ax.get_xlim() == (0.0, 255.0)
        assert grid.ticks == 4
        with pytest.raises(TypeError, match="width"):
            plot_pixel_grid(ax, 2.5, 2)
    finally:
        plt.close(fig)


BAD_VALUES = {
    "complex": [1j, 0, 0],
    "ragged": [[1, 2], [3]],
    "str": "abc",
    "bytes": b"abc",
    "dict": {"a": 1},
    "huge int": [10**400, 0, 0],
    "None": None,
}
ENTRY_POINTS = {
    "eye": lambda b: tr.Camera(eye=b, target=(0, 0, 0)),
    "fov_y": lambda b: tr.perspective(b, 1.0, 0.1, 10),
    "left": lambda b: tr.orthographic(b, 1, -1, 1, 0.1, 10),
    "axis": lambda b: tr.rotate(b, 30),
    "degrees": lambda b: tr.rotate("x", b),
    "x": lambda b: tr.translate(b, 0, 0),
    "z": lambda b: tr.seed_depth(b, 0.1, 10),
    "z_view": lambda b: tr.window_depth(b, 0.1, 10),
    "z_a": lambda b: tr.fights(b, [1, 2, 3], 0.1, 10, "unorm24"),
    "near": lambda b: tr.linear_depth([1.0], b, 10),
    "depth": lambda b: tr.quantize(b, "unorm24"),
    "points": lambda b: tr.barycentric(GOOD_XY, b),
    "f": lambda b: tr.plane_equation(GOOD_XY, b),
    "p": lambda b: tr.edge_function((0, 0), (1, 0), b),
    "a": lambda b: tr.is_top_left(b, (1, 0)),
    "sorted_xy": lambda b: tr.split_point(b),
    "colors": lambda b: tr.checkerboard(colors=b),
    "uv": lambda b: tr.sample(np.ones((2, 2)), b),
    "positions": lambda b: tr.Mesh(b, [[0, 1, 2]]),
    "name": lambda b: tr.get_scene(b),
}


@pytest.mark.parametrize("bad", sorted(BAD_VALUES))
@pytest.mark.parametrize("arg", sorted(ENTRY_POINTS))
def test_every_entry_point_names_its_argument(arg, bad):
    """Cameras, matrices, depth mappings, barycentrics, plane equations, textures, meshes and
    scenes: a ValueError/TypeError naming the argument, never a raw numpy or Python error
    (OverflowError, KeyError, IndexError, 'could not convert string to float')."""
    import re
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises((ValueError, TypeError)) as info:
            ENTRY_POINTS[arg](BAD_VALUES[bad])
    assert type(info.value) in (ValueError, TypeError)
    assert re.search(rf"\b{arg}\b", str(info.value)), str(info.value)


def test_degenerate_projections_are_refused():
    """Equal planes would divide by zero; a field of view must lie in (0, 180) degrees."""
    with pytest.raises(ValueError, match="left and right must differ"):
        tr.orthographic(1, 1, -1, 1, 0.1, 10)
    with pytest.raises(ValueError, match="near and far must differ"):
        tr.perspective(60, 1.0, 2.0, 2.0)
    with pytest.raises(ValueError, match="fov_y"):
        tr.perspective(180, 1.0, 0.1, 10)
    with pytest.raises(TypeError, match="aspect"):
        tr.perspective(60, True, 0.1, 10)
    np.testing.assert_array_equal(
        tr.perspective(np.float32(90), np.int8(1), 1, np.uint8(3)), tr.perspective(90, 1, 1, 3)
    )


def test_widget_sizes_are_python_ints():
    """The widgets take numpy integer sizes (stored as Python ints) and name a float size."""
    pytest.importorskip("ipywidgets")
    pytest.importorskip("matplotlib")
    from teachraster.widgets import FillPlayer

    t = tr.Triangle([[1, 1], [7, 2], [2, 6]])
    player = FillPlayer(t, np.uint8(8), np.int64(6), interval=np.int16(300))
    assert (player.width, player.height) == (8, 6) and type(player.width) is int
    player.close()
    with pytest.raises(TypeError, match="width"):
        FillPlayer(t, 8.0, 6)
