"""r508: exercise 6 read again after r499: a tolerance just over half a code (np.isclose)
passed 6.3, the encode done with srgb_to_linear and 6.1's floored sample offsets were misnamed,
6.2's sums divided by another count and single colours returned whole got only the staged
question; 6.3's tie margin lay below float32's rounding; 6.2's figure drew no fragment list."""

import numpy as np
import pytest

from teachraster import exercises as ex
from teachraster.exercises import resolve_codes as rc
from teachraster.exercises import resolve_fragments as rf

HEAD = (
    "import numpy as np\nimport teachraster as tr\n"
    "from teachraster import srgb_to_linear, linear_to_srgb, edge_function, snap\n"
)

RIGHT = {
    "rf_c_counter": (
        "resolve_fragments",
        "\nfrom collections import Counter\ndef resolve_fragments(fragments, sample_fragment, background):\n    c = Counter(int(j) for j in sample_fragment)\n    S = len(sample_fragment)\n    out = np.array(background, float) * c.get(-1, 0)\n    for j, n in c.items():\n        if j >= 0:\n            out = out + n * np.asarray(fragments[j], float)\n    return out / S\n",
    ),
    "rf_c_covmean_mix": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); S = len(i)\n    cov = i[i >= 0]\n    if len(cov) == 0:\n        return np.asarray(background, float)\n    m = np.asarray(fragments, float)[cov].mean(axis=0)\n    a = len(cov) / S\n    return a * m + (1 - a) * np.asarray(background, float)\n",
    ),
    "rf_c_einsum": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)\n    table = np.vstack([f, background])\n    onehot = np.eye(len(table))[np.where(i < 0, len(f), i)]\n    return np.einsum('sf,fc->c', onehot, table) / len(i)\n",
    ),
    "rf_c_list_count": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    ids = list(map(int, sample_fragment))\n    S = len(ids)\n    res = [ids.count(-1) * float(b) for b in background]\n    for j in range(len(fragments)):\n        n = ids.count(j)\n        res = [r + n * float(x) for r, x in zip(res, fragments[j])]\n    return np.array(res) / S\n",
    ),
    "rf_c_f32_bincount": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.asarray(fragments, np.float32).reshape(-1, 3); i = np.asarray(sample_fragment)\n    c = np.bincount(i[i >= 0], minlength=len(f)).astype(np.float32)\n    bg = np.asarray(background, np.float32)\n    return (c @ f + np.float32((i < 0).sum()) * bg) / np.float32(len(i))\n",
    ),
    "rf_c_keepdims_list": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    cols = np.array([background if j < 0 else fragments[j] for j in sample_fragment], float)\n    return cols.mean(axis=0).tolist()\n",
    ),
    "rf_c_background_row_last": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    f = np.vstack([np.asarray(fragments, float).reshape(-1, 3), background])\n    i = np.asarray(sample_fragment)\n    return f[i].mean(axis=0) if len(f) > 1 else np.asarray(background, float)\n",
    ),
    "cc_c_int_half": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if int(linear_to_srgb((k * fg + (S - k) * bg) / S) * 255 + 0.5) == code]\n",
    ),
    "cc_c_le_half": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    ks = np.arange(S + 1)\n    v = linear_to_srgb((ks * fg + (S - ks) * bg) / S) * 255\n    return ks[np.abs(v - code) <= 0.5].tolist()\n",
    ),
    "cc_c_weights_t": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    out = []\n    for k in range(S + 1):\n        t = k / S\n        L = t * srgb_to_linear(fg_code / 255) + (1 - t) * srgb_to_linear(bg_code / 255)\n        if np.rint(255 * linear_to_srgb(L)) == code:\n            out.append(k)\n    return out\n",
    ),
    "cc_c_f32_model": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    f = np.float32\n    fg = srgb_to_linear(f(fg_code) / f(255)); bg = srgb_to_linear(f(bg_code) / f(255))\n    ks = np.arange(S + 1, dtype=f)\n    v = np.rint(linear_to_srgb((ks * fg + (f(S) - ks) * bg) / f(S)) * f(255))\n    return [int(k) for k in ks[v == code]]\n",
    ),
    "cc_c_dict_inverse": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    table = {}\n    for k in range(S + 1):\n        L = (k * srgb_to_linear(fg_code / 255) + (S - k) * srgb_to_linear(bg_code / 255)) / S\n        table.setdefault(round(255 * float(linear_to_srgb(L))), []).append(k)\n    return table.get(code, [])\n",
    ),
    "cc_c_own_curve_pow": (
        "covered_counts",
        "\ndef dec(c):\n    return c / 12.92 if c <= 0.04045 else pow((c + 0.055) / 1.055, 2.4)\ndef enc(x):\n    return 12.92 * x if x <= 0.0031308 else 1.055 * pow(x, 1 / 2.4) - 0.055\ndef covered_counts(code, fg_code, bg_code, S):\n    return sorted({k for k in range(S + 1) if round(enc((k * dec(fg_code / 255) + (S - k) * dec(bg_code / 255)) / S) * 255) == code})\n",
    ),
    "cc_c_ceil_minus_half": (
        "covered_counts",
        "\nimport math\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if math.ceil(255 * float(linear_to_srgb((k * fg + (S - k) * bg) / S)) - 0.5) == code]\n",
    ),
}

WRONG = {
    "cc_w_neighbours": (
        "covered_counts",
        "\nimport math\ndef covered_counts(code, fg_code, bg_code, S):\n    lf = float(srgb_to_linear(fg_code / 255)); lb = float(srgb_to_linear(bg_code / 255))\n    if lf == lb:\n        return list(range(S + 1))\n    t = S * (float(srgb_to_linear(code / 255)) - lb) / (lf - lb)\n    return sorted({k for k in (math.floor(t), math.ceil(t)) if 0 <= k <= S})\n",
        "the counts either side of S·t",
    ),
    "cc_w_int_div_codes": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code // 255); bg = srgb_to_linear(bg_code // 255)\n    return [k for k in range(S + 1) if round(255 * float(linear_to_srgb((k * fg + (S - k) * bg) / S))) == code]\n",
        "with // (integer division)",
    ),
    "rf_w_int_div_weights": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3); S = len(i)\n    out = ((i < 0).sum() // S) * np.asarray(background, float)\n    for j in range(len(f)):\n        out = out + ((i == j).sum() // S) * f[j]\n    return out\n",
        "count // S (integer division)",
    ),
    "rf_w_no_divide": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    out = (i < 0).sum() * np.asarray(background, float)\n    for j in range(len(f)):\n        out = out + (i == j).sum() * f[j]\n    return out\n",
        "did not divide it by S",
    ),
    "rf_w_div_S_minus_1": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    out = (i < 0).sum() * np.asarray(background, float)\n    for j in range(len(f)):\n        out = out + (i == j).sum() * f[j]\n    return out / max(len(i) - 1, 1)\n",
        "divided it by 3 (S − 1)",
    ),
    "rf_w_unique_equal_incl_bg": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    u = np.unique(np.asarray(sample_fragment))\n    cols = [np.asarray(background, float) if j < 0 else np.asarray(fragments[j], float) for j in u]\n    return np.mean(cols, axis=0)\n",
        "each distinct index present the same weight",
    ),
    "rf_w_F_over_S_mix": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    cov = i[i >= 0]\n    if len(cov) == 0:\n        return np.asarray(background, float)\n    m = f[cov].mean(axis=0)\n    a = min(len(f) / len(i), 1.0)\n    return a * m + (1 - a) * np.asarray(background, float)\n",
        "you took F/S = 2/4",
    ),
    "rf_w_bg_if_any_uncovered": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment)\n    if (i < 0).any():\n        return np.asarray(background, float)\n    return np.asarray(fragments, float)[i].mean(axis=0)\n",
        "your answer is the background's colour alone",
    ),
    "rf_w_max_count_wins": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment)\n    u, c = np.unique(i, return_counts=True)\n    j = u[np.argmax(c)]\n    return np.asarray(background, float) if j < 0 else np.asarray(fragments[j], float)\n",
        "your answer is fragment 0's colour alone",
    ),
    "rf_w_premult_bg_by_cov": (
        "resolve_fragments",
        "\ndef resolve_fragments(fragments, sample_fragment, background):\n    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)\n    c = np.array([(i == j).sum() for j in range(len(f))])\n    a = (i >= 0).mean()\n    return (c @ f) / len(i) + a * np.asarray(background, float)\n",
        "weighed the background by the covered share",
    ),
    "cc_w_isclose_default": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    ks = np.arange(S + 1)\n    v = linear_to_srgb((ks * fg + (S - ks) * bg) / S) * 255\n    return ks[np.isclose(v, code, atol=0.5)].tolist()\n",
        "accepts more than half a code",
    ),
    "cc_w_encode_with_decode": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if round(255 * float(srgb_to_linear((k * fg + (S - k) * bg) / S))) == code]\n",
        "encoded the mixed light with srgb_to_linear",
    ),
    "cc_w_duplicates": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    out = []\n    for k in range(S + 1):\n        for j in range(S + 1):\n            if j == k and round(255 * float(linear_to_srgb((k * fg + (S - k) * bg) / S))) == code:\n                out += [k, k]\n    return out\n",
        "more than once: give each k once",
    ),
    "cc_w_one_based": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    return [k + 1 for k in range(S + 1) if round(255 * float(linear_to_srgb((k * fg + (S - k) * bg) / S))) == code]\n",
        "your k are one too many",
    ),
    "cc_w_bg_not_weighted": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if round(255 * float(linear_to_srgb(min(k * fg / S + bg, 1.0)))) == code]\n",
        "its light weighs (S − k)/S",
    ),
    "cc_w_quantised_light_inputs": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = round(float(srgb_to_linear(fg_code / 255)) * 255) / 255\n    bg = round(float(srgb_to_linear(bg_code / 255)) * 255) / 255\n    return [k for k in range(S + 1) if round(255 * float(linear_to_srgb((k * fg + (S - k) * bg) / S))) == code]\n",
        "rounded each code's light (each sample's) to 8 bits",
    ),
    "cc_w_div_S_plus_1": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    return [k for k in range(S + 1) if round(255 * float(linear_to_srgb((k * fg + (S - k) * bg) / (S + 1)))) == code]\n",
        "divided the mixed light by S + 1",
    ),
    "cc_w_gamma_2_both": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = (fg_code / 255) ** 2; bg = (bg_code / 255) ** 2\n    return [k for k in range(S + 1) if round(255 * ((k * fg + (S - k) * bg) / S) ** 0.5) == code]\n",
        "a plain power 2,",
    ),
    "cc_w_bool_mask": (
        "covered_counts",
        "\ndef covered_counts(code, fg_code, bg_code, S):\n    fg = srgb_to_linear(fg_code / 255); bg = srgb_to_linear(bg_code / 255)\n    ks = np.arange(S + 1)\n    v = np.rint(linear_to_srgb((ks * fg + (S - ks) * bg) / S) * 255)\n    return list(v == code)\n",
        "a list of bools (a mask over k = 0 … S)",
    ),
}

COVERAGE_FLOORED = "\ndef coverage_fraction(xy, pixel, samples):\n    v = snap(np.asarray(xy, dtype=float))\n    area = edge_function(v[0], v[1], v[2])\n    if area == 0:\n        return 0.0\n    if area < 0:\n        v = v[[0, 2, 1]]\n    row, col = pixel\n    points = np.floor(np.asarray(samples, dtype=float) * 256) / 256 + [col, row]\n    inside = np.ones(len(points), dtype=bool)\n    for k in range(3):\n        a, b = v[k], v[(k + 1) % 3]\n        e = edge_function(a, b, points)\n        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])\n        inside &= (e >= 0) if top_left else (e > 0)\n    return float(inside.mean())\n"


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
    assert "how much of the pixel's area" not in first, (key, first)
    assert ": ;" not in first, (key, first)


def test_floored_sample_offsets_named_as_samples_not_vertices():
    report = ex.check("coverage_fraction", _fn(COVERAGE_FLOORED, "coverage_fraction"))
    first = report.failures[0].explanation
    assert "you snapped the sample positions to the 1/256 grid too, rounding down" in first


def test_isclose_case_holds_a_value_just_past_half_a_code():
    """WP1's case: k = 3 lies 0.0022 past 223.5, inside np.isclose's rtol, off the tie margin."""
    v = rc.forward_value(3, 223, 225, 4)
    assert 0.5 < v - 223 < 0.5 + 1e-5 * 223 and rc.tie_distance(3, 223, 225, 4) > rc.TIE_MARGIN
    assert any(c[1] == (223, 223, 225, 4) for c in rc.cases())


def test_tie_margin_above_float32_rounding():
    """F1: every case's values stay farther from a tie than float32's rounding of them."""
    assert rc.TIE_MARGIN > 255 * 8 * 2.0**-24
    for _, (_code, fg, bg, s), _ in rc.cases():
        assert min(rc.tie_distance(k, fg, bg, s) for k in range(s + 1)) > rc.TIE_MARGIN


def test_fragment_figure_draws_the_fragments_and_marks_the_orphan():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    case = next(c for c in rf.cases() if "orphan fragment (overwritten)" in c[0])
    fig, ax = plt.subplots()
    rf.draw(ax, case, np.zeros(3))
    texts = [t.get_text() for t in ax.texts]
    plt.close(fig)
    assert "1:\norphan" in texts and "0: 2" in texts and "2: 2" in texts
    assert [t for t in texts if t in ("0", "2")] == ["0", "2", "2", "0"]
