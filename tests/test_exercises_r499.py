"""r499: exercise 6 read again after r490's 6.2/6.3 redesign: the wrong passes (codes over
256, float16 light), 6.3's shape words and misnamed curves, 6.2's unnamed typical mistakes, 6.1's
float16 / 4-decimal sample positions, and the correct answers that must still pass."""

import pytest

from teachraster import exercises as ex
from teachraster.exercises import tries

HEAD = "import numpy as np\nimport teachraster as tr\nfrom teachraster import srgb_to_linear, linear_to_srgb, edge_function, snap\n"

RIGHT = {
    "rf_c_unique": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)\n    out = np.zeros(3)\n    u, c = np.unique(i, return_counts=True)\n    for j, n in zip(u, c):\n        out += n * (np.asarray(background, float) if j < 0 else f[j])\n    return out / i.size\n",
    ),
    "rf_c_list_comp": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    cols = [background if j == -1 else fragments[j] for j in sample_fragment]\n    return sum(np.asarray(c, dtype=float) for c in cols) / len(cols)\n",
    ),
    "rf_c_masked_where": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment)\n    f = np.asarray(fragments, float).reshape(-1, 3)\n    if len(f) == 0:\n        return np.asarray(background, float)\n    return np.where((i >= 0)[:, None], f[np.clip(i, 0, None)], background).mean(axis=0)\n",
    ),
    "rf_c_python_lists": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    S = len(sample_fragment)\n    r = [0.0, 0.0, 0.0]\n    for s in range(S):\n        j = int(sample_fragment[s])\n        c = background if j < 0 else fragments[j]\n        for ch in range(3):\n            r[ch] += float(c[ch]) / S\n    return r\n",
    ),
    "rf_c_tuple_return_f32": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment)\n    f = np.asarray(fragments, np.float32).reshape(-1, 3)\n    w = np.array([(i == j).sum() for j in range(len(f))], np.float32)\n    res = (w @ f + np.float32((i < 0).sum()) * np.asarray(background, np.float32)) / np.float32(len(i))\n    return tuple(res)\n",
    ),
    "rf_c_matrix": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3)\n    i = np.asarray(sample_fragment)\n    table = np.concatenate([np.asarray(background, float)[None], f])\n    return np.take(table, i + 1, axis=0).mean(axis=0)\n",
    ),
    "cc_c_interval_inverse": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    out = []\n    for k in range(S + 1):\n        v = 255 * linear_to_srgb((k * lf + (S - k) * lb) / S)\n        if abs(v - code) < 0.5:\n            out.append(k)\n    return out\n",
    ),
    "cc_c_numpy_array": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    k = np.arange(S + 1)\n    lf, lb = srgb_to_linear(np.float64(fg_code) / 255), srgb_to_linear(np.float64(bg_code) / 255)\n    codes = np.rint(255 * linear_to_srgb((k * lf + (S - k) * lb) / S)).astype(int)\n    return k[codes == code]\n",
    ),
    "cc_c_float32": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    k = np.arange(S + 1, dtype=np.float32)\n    lf = srgb_to_linear(np.float32(fg_code) / np.float32(255)).astype(np.float32)\n    lb = srgb_to_linear(np.float32(bg_code) / np.float32(255)).astype(np.float32)\n    light = (k * lf + (np.float32(S) - k) * lb) / np.float32(S)\n    codes = np.rint(np.float32(255) * linear_to_srgb(light).astype(np.float32))\n    return [int(x) for x in k[codes == code]]\n",
    ),
    "cc_c_own_curves_int_half": (
        "covered_counts",
        "\ndef dec(c):\n    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4\ndef enc(x):\n    return 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055\ndef covered_counts(code, fg_code, bg_code, S):\n    res = []\n    for k in range(S + 1):\n        L = (k * dec(fg_code / 255) + (S - k) * dec(bg_code / 255)) / S\n        if int(enc(L) * 255 + 0.5) == code:\n            res.append(k)\n    return res\n",
    ),
    "cc_c_light_interval": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lo = srgb_to_linear(max(code - 0.5, 0) / 255); hi = srgb_to_linear(min(code + 0.5, 255) / 255)\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    if code == 0: lo = -1.0\n    if code == 255: hi = 2.0\n    return [k for k in range(S + 1) if lo <= (k * lf + (S - k) * lb) / S < hi]\n",
    ),
    "cc_c_samples_like_lesson": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    out = []\n    for k in range(S + 1):\n        samples = np.array([fg_code] * k + [bg_code] * (S - k)) / 255\n        shown = linear_to_srgb(srgb_to_linear(samples).mean())\n        if int(np.round(shown * 255)) == code:\n            out.append(k)\n    return out\n",
    ),
    "cc_c_tuple_np_ints": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    ks = np.arange(S + 1)\n    codes = np.round(linear_to_srgb(lb + ks / S * (lf - lb)) * 255)\n    return tuple(np.flatnonzero(codes == code))\n",
    ),
    "cc_c_descending_list": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    return [k for k in range(S, -1, -1) if round(255 * float(linear_to_srgb((k*lf + (S-k)*lb)/S))) == code]\n",
    ),
    "rf_c_bg_premult": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    cols = np.zeros((len(i), 3))\n    cols[i >= 0] = f[i[i >= 0]]\n    k = (i >= 0).mean()\n    return cols.mean(axis=0) + (1 - k) * np.asarray(background, float) * (k < 1)\n",
    ),
}

WRONG = {
    "rf_w_lesson_white": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    cols = np.ones((len(i), 3))\n    cols[i >= 0] = f[i[i >= 0]]\n    return cols.mean(axis=0)\n",
        "came out white (1, 1, 1)",
    ),
    "rf_w_clip_to_0": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3)\n    if len(f) == 0:\n        return np.asarray(background, float)\n    return f[np.maximum(sample_fragment, 0)].mean(axis=0)\n",
        "took fragment 0's colour",
    ),
    "rf_w_abs_index": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)\n    if len(f) == 0: return np.asarray(background, float)\n    return f[np.minimum(np.abs(i), len(f) - 1)].mean(axis=0)\n",
        "took fragment 0's colour",
    ),
    "rf_w_unique_positional": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)\n    u, c = np.unique(i[i >= 0], return_counts=True)\n    total = (c[:, None] * f[:len(c)]).sum(axis=0) + (i < 0).sum() * np.asarray(background, float)\n    return total / len(i)\n",
        "your counts went to other fragments",
    ),
    "rf_w_weights_by_sorted": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)\n    c = np.sort(np.bincount(i[i >= 0], minlength=len(f)))[::-1]\n    return (c @ f + (i < 0).sum() * np.asarray(background, float)) / len(i)\n",
        "your counts went to other fragments",
    ),
    "rf_w_srgb_light": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    cols = np.tile(np.asarray(background, float), (len(i), 1))\n    cols[i >= 0] = f[i[i >= 0]]\n    return linear_to_srgb(srgb_to_linear(cols).mean(axis=0))\n",
        "fragments are linear values",
    ),
    "rf_w_u8": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    cols = np.tile(np.asarray(background, float), (len(i), 1))\n    cols[i >= 0] = f[i[i >= 0]]\n    return np.round(cols.mean(axis=0) * 255) / 255\n",
        "rounded the colour to 8 bits",
    ),
    "rf_w_F0_black": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)\n    if len(f) == 0:\n        return np.zeros(3)\n    c = np.bincount(i[i >= 0], minlength=len(f))\n    return (c @ f + (i < 0).sum() * np.asarray(background, float)) / len(i)\n",
        "with no fragment stored (F = 0)",
    ),
    "rf_w_int_accumulator": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    total = np.zeros(3, dtype=int)\n    for j in sample_fragment:\n        total += np.asarray(background if j < 0 else fragments[j], float).astype(int)\n    return total / len(sample_fragment)\n",
        "truncated the colours to whole numbers",
    ),
    "rf_w_bincount_neg": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)\n    c = np.bincount(i, minlength=len(f))\n    return (c @ f + (i < 0).sum() * np.asarray(background, float)) / len(i)\n",
        "np.bincount takes no negative numbers",
    ),
    "cc_w_div256": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 256), srgb_to_linear(bg_code / 256)\n    return [k for k in range(S + 1) if round(256 * float(linear_to_srgb((k*lf + (S-k)*lb)/S))) == code]\n",
        "divided the codes by 256",
    ),
    "cc_w_float16": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf = np.float16(srgb_to_linear(fg_code / 255)); lb = np.float16(srgb_to_linear(bg_code / 255))\n    out = []\n    for k in range(S + 1):\n        L = np.float16((np.float16(k) * lf + np.float16(S - k) * lb) / np.float16(S))\n        if round(255 * float(linear_to_srgb(float(L)))) == code: out.append(k)\n    return out\n",
        "float16",
    ),
    "cc_w_decode_nolinear": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = ((fg_code / 255 + 0.055) / 1.055) ** 2.4, ((bg_code / 255 + 0.055) / 1.055) ** 2.4\n    out = []\n    for k in range(S + 1):\n        L = (k * lf + (S - k) * lb) / S\n        if round(255 * float(linear_to_srgb(L))) == code:\n            out.append(k)\n    return out\n",
        "no linear part near black",
    ),
    "cc_w_encode_nolinear": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    out = []\n    for k in range(S + 1):\n        L = (k * lf + (S - k) * lb) / S\n        if round(255 * float(1.055 * L ** (1 / 2.4) - 0.055)) == code:\n            out.append(k)\n    return out\n",
        "no linear part near black",
    ),
    "cc_w_encode_gamma22": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    out = []\n    for k in range(S + 1):\n        L = (k * lf + (S - k) * lb) / S\n        if round(255 * float(L ** (1 / 2.2))) == code:\n            out.append(k)\n    return out\n",
        "you encoded with a plain power 2.2",
    ),
    "cc_w_gamma22_decode_only": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = (fg_code / 255) ** 2.2, (bg_code / 255) ** 2.2\n    return [k for k in range(S + 1) if round(255 * float(linear_to_srgb((k*lf + (S-k)*lb)/S))) == code]\n",
        "you decoded with a plain power 2.2",
    ),
    "cc_w_ceil": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if int(np.ceil(255 * linear_to_srgb((k*lf + (S-k)*lb)/S))) == code]\n",
        "rounded 255 · encode(…) up (ceil)",
    ),
    "cc_w_tol1": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if abs(255 * linear_to_srgb((k*lf + (S-k)*lb)/S) - code) < 1]\n",
        "within one code of the code shown",
    ),
    "cc_w_light_tol": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    L = srgb_to_linear(code / 255)\n    return [k for k in range(S + 1) if abs((k*lf + (S-k)*lb)/S - L) <= 0.5 / 255]\n",
        "within half a code of light",
    ),
    "cc_w_linear8": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    target = round(255 * float(srgb_to_linear(code / 255)))\n    return [k for k in range(S + 1) if round(255 * float((k*lf + (S-k)*lb)/S)) == target]\n",
        "rounded the light to 8 bits",
    ),
    "cc_w_fg_eq_bg_empty": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    if fg_code == bg_code:\n        return []\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if round(255 * float(linear_to_srgb((k*lf + (S-k)*lb)/S))) == code]\n",
        "the answer is every k from 0 to S",
    ),
    "cc_w_fg_eq_bg_zero": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    if fg_code == bg_code:\n        return [0]\n    lf, lb = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if round(255 * float(linear_to_srgb((k*lf + (S-k)*lb)/S))) == code]\n",
        "the answer is every k from 0 to S",
    ),
    "cc_w_fg_undecoded": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = fg_code / 255, srgb_to_linear(bg_code / 255)\n    out = []\n    for k in range(S + 1):\n        L = (k * lf + (S - k) * lb) / S\n        if round(255 * float(linear_to_srgb(L))) == code:\n            out.append(k)\n    return out\n",
        "but not the triangle's",
    ),
    "cc_w_bg_undecoded": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    lf, lb = srgb_to_linear(fg_code / 255), bg_code / 255\n    out = []\n    for k in range(S + 1):\n        L = (k * lf + (S - k) * lb) / S\n        if round(255 * float(linear_to_srgb(L))) == code:\n            out.append(k)\n    return out\n",
        "but not the background's",
    ),
}

COVERAGE_WRONG = {
    "r482_reshape_transposed": (
        "\ndef coverage_fraction(xy, pixel, samples):\n    v = snap(np.asarray(xy, dtype=float))\n    area = edge_function(v[0], v[1], v[2])\n    if area == 0:\n        return 0.0\n    if area < 0:\n        v = v[[0, 2, 1]]\n    row, col = pixel\n    points = np.asarray(samples, dtype=float).T.reshape(-1, 2) + [col, row]\n    inside = np.ones(len(points), dtype=bool)\n    for k in range(3):\n        a, b = v[k], v[(k + 1) % 3]\n        e = edge_function(a, b, points)\n        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])\n        inside &= (e >= 0) if top_left else (e > 0)\n    return float(inside.mean())\n",
        "you paired the coordinates wrongly",
    ),
    "r482_bary_tol2": (
        "\ndef coverage_fraction(xy, pixel, samples):\n    v = snap(np.asarray(xy, dtype=float))\n    area = edge_function(v[0], v[1], v[2])\n    if area == 0:\n        return 0.0\n    if area < 0:\n        v = v[[0, 2, 1]]\n    row, col = pixel\n    points = np.asarray(samples, dtype=float) + [col, row]\n    inside = np.ones(len(points), dtype=bool)\n    for k in range(3):\n        a, b = v[k], v[(k + 1) % 3]\n        e = edge_function(a, b, points) / abs(area)\n        e = np.where(np.abs(e) < 1e-9, 0.0, e)\n        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])\n        inside &= (e >= 0) if top_left else (e > 0)\n    return float(inside.mean())\n",
        "a tolerance on E",
    ),
    "old_w_f16_points": (
        "\ndef coverage_fraction(xy, pixel, samples):\n    v = snap(np.asarray(xy, dtype=float))\n    area = edge_function(v[0], v[1], v[2])\n    if area == 0:\n        return 0.0\n    if area < 0:\n        v = v[[0, 2, 1]]\n    row, col = pixel\n    points = (np.asarray(samples, dtype=np.float16) + np.array([col, row], dtype=np.float16)).astype(float)\n    inside = np.ones(len(points), dtype=bool)\n    for k in range(3):\n        a, b = v[k], v[(k + 1) % 3]\n        e = edge_function(a, b, points)\n        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])\n        inside &= (e >= 0) if top_left else (e > 0)\n    return float(inside.mean())\n",
        "computed the sample positions in float16",
    ),
    "w_round_samples_4": (
        "\ndef coverage_fraction(xy, pixel, samples):\n    v = snap(np.asarray(xy, dtype=float))\n    area = edge_function(v[0], v[1], v[2])\n    if area == 0:\n        return 0.0\n    if area < 0:\n        v = v[[0, 2, 1]]\n    row, col = pixel\n    points = np.round(np.asarray(samples, dtype=float), 4) + [col, row]\n    inside = np.ones(len(points), dtype=bool)\n    for k in range(3):\n        a, b = v[k], v[(k + 1) % 3]\n        e = edge_function(a, b, points)\n        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])\n        inside &= (e >= 0) if top_left else (e > 0)\n    return float(inside.mean())\n",
        "rounded them to 4 decimals",
    ),
}


def _fn(src, name):
    ns = {}
    exec(HEAD + src, ns)
    return ns[name]


@pytest.mark.parametrize("key", sorted(RIGHT))
def test_correct_but_different_pass(key):
    name, src = RIGHT[key]
    report = ex.check(name, _fn(src, name))
    assert report.passed, (key, str(report)[:400])


@pytest.mark.parametrize("key", sorted(WRONG))
def test_wrong_named_first(key):
    name, src, words = WRONG[key]
    report = ex.check(name, _fn(src, name))
    assert not report.passed, key
    first = report.failures[0].explanation
    assert words in first, (key, first)
    assert "value(s), shape" not in first, (key, first)


@pytest.mark.parametrize("key", sorted(COVERAGE_WRONG))
def test_coverage_sample_positions_named(key):
    src, words = COVERAGE_WRONG[key]
    report = ex.check("coverage_fraction", _fn(src, "coverage_fraction"))
    assert not report.passed
    assert words in report.failures[0].explanation, report.failures[0].explanation


def test_fragments_text_says_linear_and_codes_text_says_rounded():
    import json
    from pathlib import Path

    nb = json.loads((Path(__file__).resolve().parents[1]
                     / "notebooks/exercises/06_antialiasing.ipynb").read_text())  # fmt: skip
    text = {c.get("metadata", {}).get("nbgrader", {}).get("grade_id"): "".join(c["source"])
            for c in nb["cells"]}  # fmt: skip
    assert "linear values, averaged as they are" in text["resolve_fragments_task"]
    assert "rounded to the nearest" in text["covered_counts_task"]


def test_hints_spent_do_not_change_the_names():
    tries.spend_hints(["covered_counts"])
    name, src, words = WRONG["cc_w_ceil"]
    assert words in ex.check(name, _fn(src, name)).failures[0].explanation
