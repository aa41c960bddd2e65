"""Exercise 6.2 ``resolve_fragments`` and 6.3 ``covered_counts`` (r490): students' answers.

Each is source text defining the function, run by ``tests/test_exercises_r490.py`` (and in a
fresh process by hand, for the report). RIGHT: correct but different, must pass. WRONG:
(source, words the first explanation must hold).
"""

HEAD = "import numpy as np\nfrom teachraster import srgb_to_linear, linear_to_srgb\n"

RF_RIGHT = {
    "loop": """
def resolve_fragments(fragments, sample_fragment, background):
    out = np.zeros(3)
    for i in sample_fragment:
        out = out + (np.asarray(fragments[i], float) if i >= 0 else np.asarray(background))
    return out / len(sample_fragment)
""",
    "where_index": """
def resolve_fragments(fragments, sample_fragment, background):
    f = np.asarray(fragments, float).reshape(-1, 3)
    i = np.asarray(sample_fragment)
    padded = np.vstack([f, np.asarray(background, float)[None]])
    return padded[np.where(i >= 0, i, len(f))].mean(axis=0)
""",
    "bincount": """
def resolve_fragments(fragments, sample_fragment, background):
    f = np.asarray(fragments, float).reshape(-1, 3)
    i = np.asarray(sample_fragment)
    c = np.bincount(i + 1, minlength=len(f) + 1)
    return (c[1:] @ f + c[0] * np.asarray(background)) / len(i)
""",
    "onehot": """
def resolve_fragments(fragments, sample_fragment, background):
    f = np.asarray(fragments, float).reshape(-1, 3)
    i = np.asarray(sample_fragment)
    w = (i[:, None] == np.arange(len(f))[None]).sum(axis=0) / len(i)
    return w @ f + (i < 0).mean() * np.asarray(background)
""",
    "float32": """
def resolve_fragments(fragments, sample_fragment, background):
    f = np.asarray(fragments, np.float32).reshape(-1, 3)
    i = np.asarray(sample_fragment)
    bg = np.asarray(background, np.float32)
    return np.mean([f[k] if k >= 0 else bg for k in i], axis=0)
""",
    "expand_then_mean": """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment)
    colours = np.tile(np.asarray(background, float), (len(i), 1))
    if len(fragments):
        colours[i >= 0] = np.asarray(fragments, float)[i[i >= 0]]
    return colours.mean(axis=0)
""",
}

RF_WRONG = {
    "wrap": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    return np.asarray(fragments)[sample_fragment].mean(axis=0)
""",
        "wraps",
    ),
    "per_fragment": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); u = (i < 0).mean()
    return (1 - u) * np.asarray(fragments).mean(axis=0) + u * np.asarray(background)
""",
        "the same weight",
    ),
    "mean_fragments": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    return np.asarray(fragments).mean(axis=0)
""",
        "the same weight",
    ),
    "per_used": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); u = (i < 0).mean()
    used = np.unique(i[i >= 0])
    if len(used) == 0:
        return np.asarray(background, float)
    return (1 - u) * np.asarray(fragments)[used].mean(axis=0) + u * np.asarray(background)
""",
        "the same weight",
    ),
    "orphans": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    f = np.asarray(fragments, float).reshape(-1, 3); i = np.asarray(sample_fragment)
    c = np.maximum([(i == j).sum() for j in range(len(f))], 1) if len(f) else np.zeros(0)
    u = (i < 0).sum()
    return (np.asarray(c) @ f + u * np.asarray(background)) / (np.sum(c) + u)
""",
        "no sample points at it",
    ),
    "by_sample_index": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    covered = np.asarray(sample_fragment)[:, None] >= 0
    return np.where(covered, fragments, np.asarray(background, dtype=float)).mean(axis=0)
""",
        "not fragments[s]",
    ),
    "covered_only": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float)
    if (i < 0).all():
        return np.asarray(background, float)
    return f[i[i >= 0]].mean(axis=0)
""",
        "averaged the covered samples alone",
    ),
    "black": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)
    return f[i[i >= 0]].sum(axis=0) / len(i)
""",
        "black",
    ),
    "bg_once": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)
    cov = list(f[i[i >= 0]]) + ([np.asarray(background, float)] if (i < 0).any() else [])
    return np.mean(cov, axis=0)
""",
        "background counted once",
    ),
    "by_F": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)
    return (f[i[i >= 0]].sum(axis=0) + (i < 0).sum() * np.asarray(background)) / max(len(f), 1)
""",
        "divided by F",
    ),
    "s_minus_f": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)
    return (f[i[i >= 0]].sum(axis=0) + (len(i) - len(f)) * np.asarray(background)) / len(i)
""",
        "S − F",
    ),
    "shifted": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)
    c = np.bincount(i + 1, minlength=len(f) + 1)
    return (c[:len(f)] @ f + c[0] * np.asarray(background)) / len(i)
""",
        "one fragment off",
    ),
    "div4": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)
    return (f[i[i >= 0]].sum(axis=0) + (i < 0).sum() * np.asarray(background)) / 4
""",
        "divided by 4",
    ),
    "bincount_no_minlength": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, float).reshape(-1, 3)
    c = np.bincount(i[i >= 0])
    return (c @ f + (i < 0).sum() * np.asarray(background)) / len(i)
""",
        "minlength=F",
    ),
    "float16": (
        """
def resolve_fragments(fragments, sample_fragment, background):
    i = np.asarray(sample_fragment); f = np.asarray(fragments, np.float16).reshape(-1, 3)
    bg = np.asarray(background, np.float16)
    return np.mean([f[k] if k >= 0 else bg for k in i], axis=0).astype(np.float16)
""",
        "float16",
    ),
}

CC_RIGHT = {
    "loop": """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    out = []
    for k in range(S + 1):
        if round(float(linear_to_srgb((k * fg + (S - k) * bg) / S)) * 255) == code:
            out.append(k)
    return out
""",
    "vectorised": """
def covered_counts(code, fg_code, bg_code, S):
    k = np.arange(S + 1)
    light = (k * srgb_to_linear(fg_code / 255) + (S - k) * srgb_to_linear(bg_code / 255)) / S
    return k[np.rint(linear_to_srgb(light) * 255) == code].tolist()
""",
    "own_curves": """
def covered_counts(code, fg_code, bg_code, S):
    dec = lambda c: c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    enc = lambda x: 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    a, b = dec(fg_code / 255), dec(bg_code / 255)
    return [k for k in range(S + 1) if round(enc((k * a + (S - k) * b) / S) * 255) == code]
""",
    "interval": """
def covered_counts(code, fg_code, bg_code, S):
    lo, hi = srgb_to_linear(max(code - 0.5, 0) / 255), srgb_to_linear(min(code + 0.5, 255) / 255)
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    out = []
    for k in range(S + 1):
        L = (k * fg + (S - k) * bg) / S
        if lo <= L < hi or (code == 255 and L >= lo):
            out.append(k)
    return out
""",
    "tuple_float32": """
def covered_counts(code, fg_code, bg_code, S):
    fg = srgb_to_linear(np.float32(fg_code) / 255); bg = srgb_to_linear(np.float32(bg_code) / 255)
    codes = [int(np.round(linear_to_srgb((k * fg + (S - k) * bg) / S) * 255)) for k in range(S + 1)]
    return tuple(k for k, c in enumerate(codes) if c == code)
""",
}

CC_WRONG = {
    "codes_share": (
        """
def covered_counts(code, fg_code, bg_code, S):
    if fg_code == bg_code:
        return list(range(S + 1))
    return [round(S * (code - bg_code) / (fg_code - bg_code))]
""",
        "in codes",
    ),
    "codes_forward": (
        """
def covered_counts(code, fg_code, bg_code, S):
    return [k for k in range(S + 1) if round((k * fg_code + (S - k) * bg_code) / S) == code]
""",
        "averaged the codes",
    ),
    "light_round": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    if fg == bg:
        return list(range(S + 1))
    return [int(np.round(S * (srgb_to_linear(code / 255) - bg) / (fg - bg)))]
""",
        "cannot tell them apart",
    ),
    "first_match": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    for k in range(S + 1):
        if round(float(linear_to_srgb((k * fg + (S - k) * bg) / S)) * 255) == code:
            return [k]
""",
        "cannot tell them apart",
    ),
    "none_if_ambiguous_as_empty": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    ks = [k for k in range(S + 1) if round(float(linear_to_srgb((k * fg + (S - k) * bg) / S)) * 255) == code]
    return ks if len(ks) == 1 else []
""",
        "cannot tell them apart",
    ),
    "no_255": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code), srgb_to_linear(bg_code)
    if fg == bg:
        return list(range(S + 1))
    return [int(np.round(S * (srgb_to_linear(code) - bg) / (fg - bg)))]
""",
        "/ 255",
    ),
    "truncated": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    return [k for k in range(S + 1) if int(linear_to_srgb((k * fg + (S - k) * bg) / S) * 255) == code]
""",
        "truncated",
    ),
    "gamma22": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = (fg_code / 255) ** 2.2, (bg_code / 255) ** 2.2
    return [k for k in range(S + 1) if round(((k * fg + (S - k) * bg) / S) ** (1 / 2.2) * 255) == code]
""",
        "power 2.2",
    ),
    "uncovered": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    return [S - k for k in range(S + 1)
            if round(float(linear_to_srgb((k * fg + (S - k) * bg) / S)) * 255) == code][::-1]
""",
        "uncovered samples",
    ),
    "range_S": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    return [k for k in range(S) if round(float(linear_to_srgb((k * fg + (S - k) * bg) / S)) * 255) == code]
""",
        "range(S)",
    ),
    "fraction": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    return [k / S for k in range(S + 1) if round(float(linear_to_srgb((k * fg + (S - k) * bg) / S)) * 255) == code]
""",
        "fraction k / S",
    ),
    "undecoded_compare": (
        """
def covered_counts(code, fg_code, bg_code, S):
    fg, bg = srgb_to_linear(fg_code / 255), srgb_to_linear(bg_code / 255)
    return [k for k in range(S + 1) if round((k * fg + (S - k) * bg) / S * 255) == code]
""",
        "undecoded",
    ),
}

STUBS = {
    "resolve_fragments": [
        "def resolve_fragments(fragments, sample_fragment, background):\n    raise NotImplementedError\n",
        "def resolve_fragments(fragments, sample_fragment, background):\n    return np.zeros(3)\n",
        "def resolve_fragments(fragments, sample_fragment, background):\n    return background\n",
    ],
    "covered_counts": [
        "def covered_counts(code, fg_code, bg_code, S):\n    raise NotImplementedError\n",
        "def covered_counts(code, fg_code, bg_code, S):\n    return [0]\n",
        "def covered_counts(code, fg_code, bg_code, S):\n    return list(range(S + 1))\n",
    ],
}

#: The kind of the first failure of each WRONG variant (tests/student_variants.py KINDS).
KINDS = {
    "wrap": "index −1 wraps",
    "per_fragment": "one weight per fragment",
    "mean_fragments": "one weight per fragment",
    "per_used": "one weight per fragment",
    "orphans": "orphans counted",
    "by_sample_index": "raised",
    "covered_only": "uncovered left out",
    "black": "uncovered as black",
    "bg_once": "background once",
    "by_F": "divided by F",
    "s_minus_f": "uncovered as S − F",
    "shifted": "counts shifted",
    "div4": "divided by 4",
    "bincount_no_minlength": "raised",
    "float16": "float16",
    "codes_share": "shares in codes",
    "codes_forward": "shares in codes",
    "light_round": "several k",
    "first_match": "several k",
    "none_if_ambiguous_as_empty": "several k",
    "no_255": "codes not / 255",
    "truncated": "code truncated",
    "gamma22": "power curve",
    "uncovered": "uncovered counted",
    "range_S": "k = S never tried",
    "fraction": "fraction, not count",
    "undecoded_compare": "encoded light not decoded",
}
