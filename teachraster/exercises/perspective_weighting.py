"""Exercise ``perspective_weights`` (lesson 04): the 3-D weights behind screen weights λ.

A point of the screen triangle with barycentrics λ is the image of a point of the 3-D
triangle with barycentrics μ. Its clip position is Σ μ_i P_i with w = Σ μ_i w_i, and the
divide by w gives λ_i = μ_i w_i / Σ_j μ_j w_j, so μ_i ∝ λ_i / w_i (Ek, *Triangles and
Perspective Correct Interpolation*, §2): the student derives that from the divide by w. The
cases' w run from all equal to 1e6 apart (the catalogue's ``perspective_w_ratio_1e6``) and,
since r421 T2, beyond a GPU's range too (its ``perspective_w_scale``: w near 1e-310 and 1e300),
where the formula lesson 04 prints, λ_i / w_i normalised, overflows to NaN: the graded part that
needs reasoning is a μ that only ratios of w (≤ 1, one of them exactly 1) can give (r126 D3-1
had left those w ungraded, and 3.2 was the printed formula). Any value f then interpolates as
Σ μ_i f_i.

Expected answers: :func:`teachraster.core.interpolation.weights_per_row`, the renderer's own.
"""

from __future__ import annotations

import itertools
from dataclasses import replace
from functools import lru_cache

import numpy as np

from ..core.interpolation import normalised_weights, perspective_weights, weights_per_row
from ..study.hardcases import CASES
from .answers import as_numbers
from .cases import DRAWN, SEED, drawn_rng
from .diagnosis import FLOAT32_EPS, FLOAT32_OPS, answer_in_float32, held_by_precision, near
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .interpolation import ONE_POINT
from .scalars import full_number, num, vec
from .tolerance import all_close


def weights_cases() -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (lam, w), μ): equal and unequal w, the catalogue's extreme ratios and scales."""
    rng = np.random.default_rng(SEED + 30)
    ws = [np.array([1.0, 2.0, 4.0]), np.array([3.0, 3.0, 3.0])]
    # r126 D3-1: only w a GPU meets (within float32's range): the catalogue's
    # perspective_w_scale (w ~ 1e±300, and 1e-310) tests the simulator, not the graphics
    ws += [np.asarray(w, dtype=float) for w in CASES["perspective_w_ratio_1e6"].inputs["ws"]]
    ws += list(np.exp(rng.uniform(np.log(0.1), np.log(100.0), size=(5, 3))))
    lams = [np.array([0.2, 0.3, 0.5]), np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.5, 0.5])]
    out = []
    for w in ws:
        for lam in lams + [rng.dirichlet(np.ones(3))]:
            mu = weights_per_row(lam[None], w[None])[0]
            out.append((f"λ = {vec(lam)}, w = {_ws(w)}", (lam.copy(), w.copy()), mu))
    # r46 P3: a point outside the triangle (a negative λ, as an extrapolated or clipped
    # vertex has): the same formula, and its μ is negative too. r126 D3-3: one such case of
    # 71 caught abs(λ); now six, a negative λ at each vertex, and Σ λ_i / w_i > 0 (in front)
    for lam, w in OUTSIDE:
        lam, w = np.array(lam), np.array(w)
        out.append((f"p outside the triangle: λ = {vec(lam)}, w = {_ws(w)}", (lam, w),
                    weights_per_row(lam[None], w[None], extrapolate=True)[0]))  # fmt: skip
    # r440 W1, W2: a point next to the edge opposite v1, the vertex of the smallest w: λ1 is
    # tiny but weighs 1e-4 of μ (a mask |λ| > 1e-9 dropped it), and the right terms sum to
    # 1e-6 of λ (an ε in the normaliser moved μ by 1e-6); w within a GPU's range
    for lam, w in NEAR_EDGE:
        lam, w = np.array(lam), np.array(w)
        out.append((f"p next to the edge opposite v1: λ = ({lam[0]:.3g}, {lam[1]:.12g}, "
                    f"{lam[2]:.12g}), w = {_ws(w)}", (lam, w),
                    weights_per_row(lam[None], w[None], extrapolate=True)[0]))  # fmt: skip
    now = drawn_rng()  # r46 X1: a few drawn for this check, so a harvested table fails
    for k in range(DRAWN):
        w = np.array([float(f"{x:.3g}") for x in np.exp(now.uniform(np.log(0.1), np.log(100), 3))])
        lam = np.round(now.dirichlet(np.ones(3)), 3)
        lam[2] = round(1.0 - lam[0] - lam[1], 3)  # may round to -0.001: not clamped
        mu = weights_per_row(lam[None], w[None], extrapolate=True)[0]
        out.append((f"drawn for this check {k + 1}: λ = {vec(lam)}, w = {_ws(w)}",
                    (lam.copy(), w.copy()), mu))  # fmt: skip
    # r421 T2: w beyond a GPU's range, graded, last (a slip of the formula fails first where
    # it does): the catalogue's perspective_w_scale and points on an edge (:data:`EXTREME`)
    for lam, w in EXTREME:
        lam, w = np.array(lam, dtype=float), np.array(w, dtype=float)
        outside = "p outside the triangle, " if (lam < 0).any() else ""  # r429 W1
        out.append((f"{outside}w beyond a GPU's range: λ = {vec(lam)}, w = {_ws(w)}", (lam, w),
                    weights_per_row(lam[None], w[None], extrapolate=True)[0]))  # fmt: skip
    return out


#: r421 T2: (λ, w) with w beyond float32's range (``perspective_w_scale``'s scales 1e300,
#: 1e-300, 1e-310 of w = (1, 2, 4)), where λ_i / w_i overflows at 1e-310 and a product of two
#: w at 1e300; w 1e610 apart, where a ratio of w above 1 overflows; then points on an edge
#: whose opposite vertex holds the smallest w, where every term scaled by that w underflows
EXTREME = (
    # r429 M1: first, a case where only λ_i / w_i makes a NaN (1 / 1e-310 overflows; no ratio
    # of w nor product of two leaves float64's range): the printed formula's NaN, said as such
    ((0.2, 0.3, 0.5), (1e-310, 1e-3, 1e-2)),
    *(((0.2, 0.3, 0.5), (s, 2 * s, 4 * s)) for s in (1e-310, 1e-300, 1e300)),
    ((1.0, 0.0, 0.0), (1e-310, 2e-310, 4e-310)),
    ((0.2, 0.3, 0.5), (1e-310, 1e300, 1e300)),
    ((0.2, 0.3, 0.5), (1e300, 2e300, 1e-310)),
    ((0.0, 0.5, 0.5), (1e-310, 1e300, 1e300)),
    ((0.5, 0.5, 0.0), (1e300, 2e300, 1e-310)),
    # r429 W1: a negative λ at the vertex of the smallest w (an extrapolated point): a
    # reference w taken among the λ > 0 only overflows its ratio there
    ((-0.25, 0.5, 0.75), (1e-310, 1e300, 1e300)),
    ((0.5, 0.75, -0.25), (1e300, 1e300, 1e-310)),
    # r440 W3: w1 = 1e-320, 1e620 from the others: a reference w from the extremes (their
    # geometric mean, 1e-10) overflows its ratio to w1, though 1e-310 to 1e300 did not
    ((0.2, 0.3, 0.5), (1e-320, 1e300, 1e300)),
    # r455 W3: the catalogue's w = (1, 2, 4) scaled to 1e-320: λ_i · w_ref (2e-321 at v1)
    # is subnormal, with about 9 significant bits, so (λ_i · w_ref) / w_i was off by 1.6e-4;
    # λ_i · (w_ref / w_i) is exact (ratios 1, ½, ¼)
    ((0.2, 0.3, 0.5), (1e-320, 2e-320, 4e-320)),
    # r455 W2: a λ 1e300 below the others at the vertex of the smallest w, which weighs half
    # of μ: a mask |λ| > ε with ε down to 1e-300 drops it (the tiny λ of :data:`NEAR_EDGE`
    # stop at 1e-12); no product here leaves float64's normal range
    # (w2 ≠ w3, so the answer without λ1, (0, ⅔, ⅓), is not λ itself: "you returned λ")
    ((1e-300, 0.5, 0.5), (1.0, 1e300, 2e300)),
    # r495 (r455's left-over): a subnormal λ1 = 1e-310 at w1 = 1e-10, again half of μ: a mask
    # |λ| > np.finfo(float).tiny (2.2e-308, float64's smallest normal number) dropped it. The
    # right order's terms λ_i · (w_ref / w_i) are subnormal too (1e-310, 5e-311, 2.5e-311) but
    # keep about 43 bits, so μ = (4/7, 2/7, 1/7) to 1e-13; (λ_i · w_ref) / w_i is not (1e-320)
    ((1e-310, 0.5, 0.5), (1e-10, 1e300, 2e300)),
)

#: r440 W1, W2: (λ, w) of a point next to an edge, whose tiny λ sits at the smallest w
NEAR_EDGE = (
    ((1e-10, 0.5, 0.4999999999), (1e-3, 1e3, 1e3)),
    # λ1 = 1e-12 at w1 = 1e-9: half of μ (np.isclose(λ, 0) and |λ| > 1e-12 drop it)
    ((1e-12, 0.5, 0.499999999999), (1e-9, 1e3, 1e3)),
)

#: (λ, w) of points outside the triangle: one negative λ each
OUTSIDE = (
    ((-0.25, 0.5, 0.75), (1.0, 2.0, 4.0)),
    ((1.5, -0.75, 0.25), (1.0, 2.0, 4.0)),
    ((0.6, 0.7, -0.3), (10.0, 1.0, 3.0)),
    ((1.2, -0.4, 0.2), (4.0, 1.0, 0.5)),
    ((-0.5, 0.75, 0.75), (3.0, 1.0, 2.0)),
    ((0.25, 1.25, -0.5), (1e-3, 1.0, 1e3)),
)


def beyond_a_gpu(label: str) -> bool:
    """Whether case ``label`` has a w outside float32's range (1e-310, 1e300): only a
    simulator meets such w (lesson 07's summary), so neither the capstone (r126 D12-1) nor,
    since r126 D3-1, this exercise's check holds one; kept as the capstone's guard."""
    return label in _beyond_a_gpu()


@lru_cache(maxsize=1)
def _beyond_a_gpu() -> frozenset:
    return frozenset(label for label, (_, w), _ in weights_cases() if _beyond(w))


def _ws(w) -> str:
    return "(" + ", ".join(f"{x:.3g}" for x in w) + ")"


def as_weights(value) -> np.ndarray:
    return as_numbers(value, (3,), "3 weights, shape (3,)")


#: r455 W1: how many freed buffers of each small size are filled with NaN before each call
#: (numpy keeps up to 7 freed buffers per size, and hands them out again uncleared)
POISONED = 8


def poison_freed_memory() -> None:
    """Fill the small buffers numpy keeps for reuse with NaN, so that an entry a function
    never writes (``np.divide(..., where=...)`` without ``out=``, ``np.empty``) reads NaN
    on every run, not whatever the memory held (r440 H2, r455 W1: zeros in most runs, so
    such a function passed, and ``... * λ`` turned any finite garbage into 0)."""
    for n in range(1, 10):  # 8 to 72 bytes: three weights in float64, float32, (1, 3)...
        junk = [np.full(n, np.nan) for _ in range(POISONED)]
        del junk


def call_weights(fn, args) -> np.ndarray:
    """The student's weights, the call made on poisoned freed memory (:func:`poison_freed_memory`)."""
    poison_freed_memory()
    return as_weights(fn(*args))


def same_weights(got: np.ndarray, expected: np.ndarray, args=None) -> bool:
    return bool(np.isfinite(got).all()) and all_close(got, expected)


def _variants(lam, w) -> dict[str, np.ndarray]:
    with np.errstate(all="ignore"):
        mu = weights_per_row(lam[None], w[None], extrapolate=True)[0]
        return {
            "affine": lam,
            "times w": lam * w / (lam @ w),
            "unnormalised": lam / w,
            "unnormalised times w": lam * w,
            # r94 D3-3: the package's own default (clamping) was told to "make the weights
            # sum to 1"; said only where a λ is negative (elsewhere it is the right answer)
            "clamped": weights_per_row(lam[None], w[None])[0] if (lam < 0).any() else None,
            # r126 D3-3: abs(λ) got only the general rule
            "absolute": _normalised(np.abs(lam) * (w.min() / w)) if (lam < 0).any() else None,
            # r137: three half-named (the sum, or the general rule, only)
            "absolute sum": (lam / w) / np.abs(lam / w).sum() if (lam < 0).any() else None,
            "no lambda": _normalised(1 / w),
            "w reversed": _normalised(lam / w[::-1]),
            # r164 B5: six more got only "write λ_i in terms of μ ..."
            **{f"no 1/w at v{k + 1}": _normalised(np.where(np.arange(3) == k, lam, lam / w))
               for k in range(3)},
            "divided by w twice": _normalised(lam / w**2),
            "clipped": (_normalised(np.clip(lam, 0.0, 1.0) / w)
                        if ((lam < 0) | (lam > 1)).any() else None),
            "sum of 1/w": (lam / w) / np.sum(1 / w),
            **{f"no 1/w in the sum at v{k + 1}": (lam / w) / (np.sum(lam / w) - lam[k] / w[k]
                                                           + lam[k]) for k in range(3)},
            # r348 item 4: the point's w taken as Σ λ_j w_j (w affine on the screen), and
            # λ_i / w_i divided by the largest of them
            "w interpolated linearly": (lam / w) * (lam @ w),
            "normalised by the largest": (lam / w) / np.max(lam / w),
            # r358 6: μ itself clamped, to [0, 1] or at 0, renormalised or not (the clamp of λ
            # is "clamped" and "clipped" above)
            **_clamped_mu(_normalised(lam / w)),
            # r358 7, 8: λ_i / w_i divided by Σ λ_j w_j, or multiplied by the mean w
            "divided by Σλw": (lam / w) / (lam @ w),
            "times the mean w": (lam / w) * np.mean(w),
            # r421 H5: μ right, returned in another order (μ reversed, or rolled)
            **{f"μ in the order {k}": mu[list(order)] for k, order in MU_ORDERS.items()},
            # r421 H6: μ inside the triangle, λ itself outside it
            "λ outside": lam if (lam < 0).any() else None,
        }  # fmt: skip


def _beyond_variants(lam, w) -> dict[str, np.ndarray]:
    """r421 T2: right on a GPU's w, NaN (or 0) beyond: λ_i / w_i as lesson 04 prints it,
    scaled by the smallest w of all, by the largest, by w1, the products of the other two w,
    and through the point's w, 1 / Σ λ_j / w_j."""
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    with np.errstate(all="ignore"):
        return {
            "λ/w overflows": _normalised(lam / w),
            "smallest w of all": _normalised(lam * (w.min() / w)),
            "largest w": _normalised(lam * (w.max() / w)),
            "w1": _normalised(lam * (w[0] / w)),
            "products of w": _normalised(lam * np.array([w[1] * w[2], w[2] * w[0], w[0] * w[1]])),
            "the point's w": lam * (1 / np.sum(lam / w)) / w,
            # r455 W3: the right reference, multiplied into λ before the divide by w
            "λ times w_ref first": _normalised(np.where(lam != 0, lam * _w_ref(lam, w), 0.0) / w),
        }  # fmt: skip


def _w_ref(lam, w) -> float:
    """The smallest w among the vertices whose λ is not 0 (the right reference)."""
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    return float(w[lam != 0].min()) if (lam != 0).any() else float("nan")


def _beyond_slip(kind: str):
    """``fits`` of one of :func:`_beyond_variants`: its very answer, in float64 (a float32
    answer's NaN is float32's, said by the checker's own words, not a formula's)."""

    def fits(args, expected, got):
        if answer_in_float32(got) or not _beyond(args[1]) or _holds_nan(got):
            return None  # (on a GPU's w it is the right answer: a near one is no overflow;
            # r429 M1: a NaN is told by the case's sources, :func:`_nan_sources`)
        slip = _beyond_variants(*args)[kind]
        if np.isfinite(slip).all() and all_close(slip, expected):
            return None  # r440 M1: right here (the smallest w of all where its λ is not 0)
        return near(slip, got)

    return fits


def _holds_nan(value) -> bool:
    """Does an answer hold NaN (read as numbers; anything else does not)?"""
    try:
        return bool(np.isnan(np.asarray(value, dtype=float)).any())
    except (TypeError, ValueError):
        return False


def match_weights(got, answer, args) -> bool:
    """Does the student's answer equal what a mistake gives? Never by NaN == NaN (r429 M1,
    M2: every computation that ends in 0 · inf, 0 / 0 or inf / inf gives the same NaN, so a
    NaN answer was told the first slip of the table that makes one; it is told by the
    case's sources instead, :data:`NAN_BEYOND`)."""
    return not _holds_nan(got) and near(answer, got)


def _vertices(ks) -> str:
    names = [f"v{k + 1}" for k in ks]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _nan_sources(lam, w) -> list[str]:
    """r429 M1: every step that makes a NaN on a case beyond a GPU's range, each with the
    vertex whose term it spoils and how (0 · inf, 0 / 0, inf / inf)."""
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    said = []
    with np.errstate(all="ignore"):
        over = [k for k in range(3) if lam[k] != 0 and np.isinf(lam[k] / w[k])]
        if over:
            # r440 H4: λ and w both scaled by 1e-300 make the same inf (w1 · 1e-300 is 0)
            said.append(f"λ_i / w_i overflows to inf at {_vertices(over)} (1 / {w[over[0]]:.3g} "
                        "is beyond float64's largest number; so does a λ divided by a w scaled "
                        "down to 0), and inf / inf is NaN")  # fmt: skip
        for k in np.flatnonzero(lam == 0):
            far = [j for j in range(3) if lam[j] != 0 and w[j] / w[k] in (0.0, np.inf)]
            if far:
                j = far[0]
                said.append(
                    f"λ{k + 1} = 0 and w{k + 1} = {w[k]:.3g} lies beyond float64's range from "
                    f"w{j + 1} = {w[j]:.3g}: a ratio of w{k + 1} to w{j + 1} is 0 or inf, so a "
                    f"term of v{k + 1} computed from one (λ{k + 1} times inf, or λ{k + 1} / 0) is "
                    "0 · inf or 0 / 0, NaN, even where you scaled by the right w: leave the term "
                    "of a vertex whose λ is 0 at 0, without computing it")  # fmt: skip
        k = int(np.argmin(w))
        if lam[k] == 0 and not (lam * (w[k] / w)).any():
            said.append(f"scaled by the smallest w of all, w{k + 1} (whose λ is 0), every other "
                        f"term λ_i · (w{k + 1} / w_i) underflows to 0, and 0 / 0 is NaN")  # fmt: skip
        said += _ratio_sources(lam, w)
        products = np.array([w[1] * w[2], w[2] * w[0], w[0] * w[1]])
        if not (np.isfinite(products) & (products > 0)).all():
            said.append(f"a product of two w leaves float64's range ({_products((lam, w))}): "
                        "inf times a λ of 0, 0 / 0 or inf / inf is NaN")  # fmt: skip
    return said


def _ratio_sources(lam, w) -> list[str]:
    """A ratio of w above 1 that overflows at a vertex whose λ is not 0 (a scale w larger
    than its own); r429 W1: the reference taken among the λ > 0 only, where a negative λ sits
    at the smallest w."""
    said = []
    live = lam != 0
    for k in np.flatnonzero(live):
        big = [j for j in range(3) if j != k and w[j] / w[k] == np.inf]
        if not big:
            continue
        j = big[0]
        words = (f"a scale w larger than w{k + 1} = {w[k]:.3g} (w{j + 1} = {w[j]:.3g}, say) makes "
                 f"its ratio w{j + 1} / w{k + 1} overflow to inf at v{k + 1}, and inf / inf is NaN")  # fmt: skip
        if lam[k] < 0 and w[k] == w[live].min():
            ref = int(np.flatnonzero(lam > 0)[np.argmin(w[lam > 0])])
            words += (f" (λ{k + 1} < 0 here: the smallest w among the λ > 0 only, w{ref + 1}, is "
                      "such a scale; take the smallest w among every λ ≠ 0, whatever its sign)")  # fmt: skip
        said.append(words)
    return said


def _says_no_nan(m: Mistake) -> Mistake:
    """``m`` saying nothing where it gives NaN (r429 M1: every NaN is the same NaN, so a
    NaN the mistake gives neither matches nor contradicts the student's)."""
    if m.gives is None:
        return m

    def gives(*args):
        value = m.gives(*args)
        return None if _holds_nan(value) else value

    return replace(m, gives=gives)


def _nan_beyond_fits(args, expected, got):
    if answer_in_float32(got) or not _beyond(args[1]) or not _holds_nan(got):
        return None
    return bool(_nan_sources(*args))


def _nan_beyond_words(args, expected, got) -> str:
    sources = _nan_sources(*args)
    if len(sources) == 1:
        return f": on this case only an infinite term makes a NaN: {sources[0]}. {ONLY_RATIOS}"
    listed = "; ".join(f"({n + 1}) {s}" for n, s in enumerate(sources))
    return (
        f": your NaN does not tell which step made it, but on this case only these make one: "
        f"{listed}. {ONLY_RATIOS}"
    )


#: r429 M1, M2: a NaN beyond a GPU's range, told by what makes one on the case
NAN_BEYOND = Mistake("NaN beyond a GPU's range", _nan_beyond_words, fits=_nan_beyond_fits)


def _weights_raised(args, error: str) -> str:
    """r429 H4: an OverflowError (math.exp beyond 709.78) said with its cause."""
    if "OverflowError" not in error:
        return ""
    lam, w = (np.asarray(a, dtype=float) for a in args)
    logs = np.log(w)
    gap = float(logs.max() - logs.min())
    return (
        " (math.exp, or a power, overflows where float64 ends: exp(x) for x above 709.78; "
        f"here the logs of the w lie {gap:.1f} apart: a term exp(x_i) of the log domain was "
        "not shifted by the largest x_i, so that every x_i ≤ 0, or a vertex whose λ is 0 had "
        "its term computed: leave that term 0)"
    )


#: r421 H5: μ in another order, each vertex's index in the answer
MU_ORDERS = {"μ3, μ2, μ1": (2, 1, 0), "μ2, μ3, μ1": (1, 2, 0), "μ3, μ1, μ2": (2, 0, 1),
             "μ2, μ1, μ3": (1, 0, 2), "μ1, μ3, μ2": (0, 2, 1)}  # fmt: skip


def _clamped_mu(mu: np.ndarray) -> dict[str, np.ndarray | None]:
    """μ clipped to [0, 1] or at 0, as is and renormalised: only where it changes μ."""
    out = {}
    for upper, named in ((1.0, "μ clipped"), (np.inf, "μ clamped at 0")):
        kept = np.clip(mu, 0.0, upper)
        changed = not np.array_equal(kept, mu)
        out[named] = kept if changed else None
        out[f"{named}, renormalised"] = _normalised(kept) if changed and kept.sum() else None
    return out


def _normalised(q: np.ndarray) -> np.ndarray:
    return q / q.sum()


#: r348 item 4: the words that give the repair away, staged as hints (:data:`HINTS`)
W_NOT_AFFINE = ("w is not affine on the screen, 1/w is: the point's 1/w is Σ λ_j / w_j, the "
                "sum of your own three numerators")  # fmt: skip
BY_THEIR_SUM = "weights sum to 1, so divide by their sum"


def _clamped_mu_words(args, expected, got) -> str:
    """r358 6: the clamp of μ itself, with what it broke."""
    summed = "" if _sums_to_1(got) else f", and yours sum to {_their_sum(got)}, not 1"
    return (
        "you clamped your weights (to [0, 1], or at 0): the point lies outside the triangle (as "
        "a clipped or extrapolated one does), and its weights are not clamped here: a negative "
        f"λ gives a negative μ{summed}"
    )


MISTAKES = {
    "affine": "these are the screen weights λ themselves: that is affine interpolation, "
    "right only when the three w are equal",
    "times w": "you multiplied λ by w: the screen position divides by w, so the 3-D "
    "weights go as λ_i / w_i, not λ_i · w_i",
    "unnormalised": "these are λ_i / w_i, not yet weights: they must sum to 1 (divide by "
    "their sum Σ λ_j / w_j, the interpolated 1/w)",
    "unnormalised times w": "these are λ_i · w_i, neither divided by w nor summing to 1",
    "clamped": "your weight is 0 where λ is negative: the point lies outside the triangle "
    "(as a clipped or extrapolated one does), and its weights are not clamped here: a "
    "negative λ gives a negative μ",
    "absolute": "your weights are all positive, but one λ is negative: you took abs(λ) "
    "(or the size of each weight); the point lies outside the triangle, and each μ keeps the "
    "sign of its λ (every w is positive): a negative λ gives a negative μ",
    "absolute sum": "you divided by the sum of the sizes |λ_j / w_j|: one λ is negative here, "
    "so that sum is larger than the signed one and your weights do not sum to 1; divide by "
    "the signed sum",
    "no lambda": "your weights leave λ out: they are the same at every point of the triangle, "
    "while each μ_i must be 1 at its vertex v_i (where λ_i is 1) and 0 on the edge opposite",
    "w reversed": "you paired λ_i with another vertex's w (the w in reverse order): each "
    "vertex's λ goes with that vertex's own w",
    **{f"no 1/w at v{k + 1}": f"your weight of v{k + 1} leaves out its 1/w: λ{k + 1} itself, "
       "where the other two are divided by their w before the three are normalised; every "
       "vertex's λ is divided by its own w" for k in range(3)},
    "divided by w twice": "you divided each λ by its w twice (λ_i / w_i²): the screen position "
    "divides by w once",
    "clipped": "you clipped λ to [0, 1] before weighting: the point lies outside the triangle "
    "(as a clipped or extrapolated one does), and its weights are not clamped here: a negative "
    "λ gives a negative μ",
    "sum of 1/w": "you divided by Σ 1/w_j, the three 1/w alone: that sum leaves the λ out, so "
    "your weights do not sum to 1; divide by the sum of your own three numerators",
    **{f"no 1/w in the sum at v{k + 1}": f"the sum you divide by holds λ{k + 1} itself where "
       f"your numerator of v{k + 1} has λ{k + 1} / w{k + 1}: divide by the sum of your own "
       "three numerators" for k in range(3)},
    "w interpolated linearly": lambda a, e, g: (
        "you took the point's w as Σ λ_j w_j, w interpolated linearly on the screen, and "
        f"divided λ_i / w_i by its 1/w, so your weights sum to {_their_sum(g)}, not 1: "
        f"{W_NOT_AFFINE}"),
    "normalised by the largest": lambda a, e, g: (
        "you divided your λ_i / w_i by the largest of them: the largest weight is then 1 "
        f"and they sum to {_their_sum(g)}; {BY_THEIR_SUM}"),
    **{k: _clamped_mu_words for k in ("μ clipped", "μ clipped, renormalised", "μ clamped at 0",
                                      "μ clamped at 0, renormalised")},
    "divided by Σλw": lambda a, e, g: (
        "you divided your λ_i / w_i by Σ λ_j w_j, the point's w interpolated linearly on the "
        f"screen, so your weights sum to {_their_sum(g)}, not 1; {BY_THEIR_SUM}"),
    "times the mean w": lambda a, e, g: (
        "you multiplied your λ_i / w_i by the mean of the three w, so your weights sum to "
        f"{_their_sum(g)}, not 1: the mean w is no normaliser; {BY_THEIR_SUM}"),
    **{f"μ in the order {k}": (
        f"your weights are the right ones in another order, ({k}): μ_i belongs to vertex i, "
        "the vertex of λ_i and w_i; return them in the vertices' order") for k in MU_ORDERS},
    "λ outside": (
        "inside the triangle your weights are right, but here a λ is negative (the point lies "
        "outside, as a clipped or extrapolated one does) and you returned λ itself, the affine "
        "weights: the same μ_i ∝ λ_i / w_i holds outside, and gives a negative μ"),
}  # fmt: skip

#: r429 H2: λ itself returned on w beyond a GPU's range (a fallback, or the w clipped), said
#: where the answer is λ (a fallback on some of those cases only is no formula's answer)
LAM_BEYOND = Mistake(
    "λ beyond a GPU's range",
    lambda a, e, g: (
        f"on these w, {_ws(a[1])}, beyond a GPU's range, you returned λ itself, the affine "
        f"weights: right only were the three w equal (a fallback, or the w clipped?). "
        f"{ONLY_RATIOS}"),
    fits=lambda a, e, g: near(np.asarray(a[0], dtype=float), g) if _beyond(a[1]) else None,
)  # fmt: skip

#: r421 T2: the words of :func:`_beyond_variants`' slips
BEYOND = {
    "λ/w overflows": lambda a, e, g: _overflow_words(a),
    # (fitted on the failing cases alone: the slip that fails fewer cases first, since it
    # fits every NaN of the other on them: the smallest w of all, w1, the largest w)
    "smallest w of all": lambda a, e, g: _underflow_words(a),
    "w1": lambda a, e, g: _ratio_words(a, "w1", a[1][0], "w1"),
    "largest w": lambda a, e, g: _ratio_words(a, "the largest w", np.max(a[1]), "w_max"),
    "products of w": lambda a, e, g: (
        f"your terms λ_i times the other two w left float64's range (here {_products(a)}): a "
        f"product of two w overflows or underflows long before the w do. {ONLY_RATIOS}"),
    "λ times w_ref first": lambda a, e, g: _subnormal_words(a),
    # r429 H3: what the sum does, not which route used it (np.nan_to_num gives the same 0s)
    "the point's w": lambda a, e, g: (
        f"your weights are all 0: Σ λ_j / w_j = {_sum_q(a)} here ({OVERFLOW}), and a number "
        f"divided by it, or times the point's w taken as 1 / Σ λ_j / w_j, is 0. {ONLY_RATIOS}"),
}  # fmt: skip

#: r421 T2: the one sentence on why ratios of w are the repair (staged: :data:`HINTS`)
ONLY_RATIOS = ("μ depends only on the ratios of the w (every w times one number gives the same "
               "μ): scale each λ_i / w_i by the smallest w among the vertices whose λ is not 0, "
               "so every ratio is at most 1 and that vertex's term is its λ itself")  # fmt: skip
#: r421 T2: float64's range, said once for every overflow
OVERFLOW = "float64's largest number is 1.8e308, its smallest above 0 is 5e-324"


def _q_words(lam, w) -> str:
    with np.errstate(all="ignore"):
        return vec(np.asarray(lam, float) / np.asarray(w, float))


def _sum_q(args) -> str:
    lam, w = args
    with np.errstate(all="ignore"):
        return num(float(np.sum(np.asarray(lam, float) / np.asarray(w, float))))


def _products(args) -> str:
    _, w = args
    with np.errstate(all="ignore"):
        return "w2·w3, w3·w1, w1·w2 = " + vec([w[1] * w[2], w[2] * w[0], w[0] * w[1]])


def _overflow_words(args) -> str:
    lam, w = args
    return (
        f"your λ_i / w_i = {_q_words(lam, w)} overflowed ({OVERFLOW}: 1 / {w.min():.3g} is "
        f"beyond it), and inf / inf is NaN. {ONLY_RATIOS}"
    )


def _underflow_words(args) -> str:
    lam, w = args
    k = int(np.argmin(w))
    return (
        f"you scaled by the smallest w of all, w{k + 1} = {w[k]:.3g}, but λ{k + 1} = 0: the "
        f"other terms, λ_i · ({w[k]:.3g} / w_i), underflowed to 0 ({OVERFLOW}), and 0 / 0 is "
        "NaN. Scale by the smallest w among the vertices whose λ is not 0: that vertex's term "
        "is its λ itself, so the sum cannot underflow to 0"
    )


def _subnormal_words(args) -> str:
    """r455 W3: (λ_i · w_ref) / w_i, whose products are subnormal numbers."""
    lam, w = (np.asarray(a, dtype=float) for a in args)
    ref = _w_ref(lam, w)
    k = int(np.argmin(np.where(lam != 0, np.abs(lam * ref), np.inf)))
    product = abs(float(lam[k] * ref))
    bits = max(1, int(np.floor(np.log2(product / np.nextafter(0.0, 1.0)))) + 1)
    return (
        f"you scaled by the right w, w_ref = {ref:.3g}, but multiplied it into λ before dividing "
        f"by w: λ{k + 1} · w_ref = {product:.3g} lies below float64's smallest normal number, "
        f"2.2e-308, where a float keeps only {bits} significant bits, not 53, so your terms "
        "lost their digits. Divide first: λ_i · (w_ref / w_i), whose ratio is at most 1 and "
        "exactly 1 at the reference vertex"
    )


def _ratio_words(args, which: str, by: float, short: str) -> str:
    lam, w = args
    with np.errstate(all="ignore"):
        ratios = by / np.asarray(w, float)
    went = "overflowed" if (ratios == np.inf).any() else "underflowed to 0"
    return f"you scaled each λ_i / w_i by {which}, {by:.3g}: the ratios {short} / w_i = {vec(ratios)} {went} ({OVERFLOW}). {RATIO_REPAIR}"


#: r421 T2: which ratios of w are safe (staged: :data:`HINTS`)
RATIO_REPAIR = ("A ratio of w can neither overflow nor vanish only when it is at most 1 and one "
                "of them is 1 where λ is not 0: scale by the smallest w among the vertices "
                "whose λ is not 0")  # fmt: skip


def _paired(sigma):
    """λ_i divided by w_σ(i), normalised: λ paired with another vertex's w (r164 B5: w
    shifted by one place, or μ2 computed with w1, got only the rule)."""

    def gives(lam, w):
        with np.errstate(all="ignore"):
            return _normalised(np.asarray(lam) / np.asarray(w)[list(sigma)])

    return gives


def _paired_words(sigma) -> str:
    pairs = [f"λ{i + 1} with w{j + 1}" for i, j in enumerate(sigma) if i != j]
    listed = pairs[0] if len(pairs) == 1 else ", ".join(pairs[:-1]) + " and " + pairs[-1]
    return (f"you paired {listed}: each vertex's λ goes with that vertex's own w (the same "
            "place in w)")  # fmt: skip


#: Every other way of pairing the three λ with the three w (the reversal is "w reversed").
PAIRINGS = [
    Mistake("w of another vertex", _paired_words(sigma), gives=_paired(sigma))
    for sigma in itertools.product(range(3), repeat=3)
    if sigma not in ((0, 1, 2), (2, 1, 0))
]


def explain_weights(args, expected, got) -> str:
    """The case, the student's weights and the 3-D ones."""
    lam, w = args
    return (
        f"at λ = {vec(lam)} and w = {_ws(w)} your weights are {_yours(got, expected)}; the 3-D "
        f"weights are μ = {vec(expected, got)}"
    )


def _yours(got, expected) -> str:
    """The student's weights with the digits that tell them from μ, or, where they have few
    decimals (rounded), every digit they have (r421 S3: 0.42105 was printed 0.421 beside
    μ1 = 0.4211)."""
    g = np.asarray(got, dtype=float)
    if g.shape == (3,) and np.isfinite(g).all() and np.array_equal(np.round(g, 8), g):
        return "(" + ", ".join(full_number(x) for x in g) + ")"
    return vec(got, expected)


def _sums_to_1(got) -> bool:
    """Do the weights sum to 1 (to float noise: float64's, or the rounding of the precision
    they are in, r163 12-7: float32 weights summing to 0.9999999, one float32 step from 1,
    were told "they sum to 0.9999999, and weights sum to 1")? One test for every text that
    says so."""
    from .diagnosis import FLOAT32_OPS, precision_of
    from .value_checks import float_type

    noise = 1e-12 if float_type(got) is None else FLOAT32_OPS * precision_of(got)[1]
    return abs(float(np.sum(got)) - 1) <= noise


def _sums_to_other_than_1(got) -> bool:
    """A finite sum other than 1 (NaN is told NaN, not "they sum to nan")."""
    return bool(np.isfinite(np.sum(got))) and not _sums_to_1(got)


def _their_sum(got) -> str:
    """The weights' sum, with the digits that tell it from 1 (r153 D3-4: 0.999999999 was
    printed "1" beside "and weights sum to 1"): the one place that formats it."""
    return num(float(np.sum(got)), 1.0)


def _rule(args, expected, got) -> str:
    # r94 D3-3: "make the weights sum to 1" was told to weights that did
    if _sums_to_1(got):
        return " (μ_i ∝ λ_i / w_i; yours already sum to 1)"
    return " (μ_i ∝ λ_i / w_i, normalised to sum to 1)"


def _sum_words(args, expected, got) -> str:
    """r495 H4: weights proportional to μ but not summing to 1 (``q / (q.sum() + 1e-300)``
    where the check reads no ε back) are told so, not only their sum."""
    total = float(np.sum(got))
    g = np.asarray(got, dtype=float)
    if total != 0 and all_close(g / total, np.asarray(expected, dtype=float)):
        return (f": they sum to {_their_sum(got)}, not 1, and they are the right weights μ "
                f"times that number: proportional to μ, but divided by something other than the "
                "sum of your terms (a small number added to it, or another term's sum?); "
                "divide by that sum itself")  # fmt: skip
    return f": they sum to {_their_sum(got)}, and weights sum to 1"


def _nudge(args, got, small: bool = True) -> float | None:
    """δ when ``got`` is λ_i/w_i ÷ (Σ λ_j/w_j + δ) for a small δ ≠ 0 (a guard against
    dividing by 0), else None; ``small=False``: any δ up to the sum itself (r440 W2: an ε
    beside terms scaled by a tiny w is not small beside them)."""
    lam, w = args
    g = np.asarray(got, dtype=float)
    total = float(np.sum(g))
    if g.shape != (3,) or not np.isfinite(g).all() or total == 0 or _sums_to_1(g):
        return None
    with np.errstate(all="ignore"):
        q = lam / w
    s = float(np.sum(q))
    if not np.isfinite(s) or s == 0:
        return None
    delta = s / total - s
    # r164: a guard adds a positive ε (the sum is positive: the point is in front); one ε
    # on every case (:attr:`.Mistake.parameter`): Σ 1/w_j for Σ λ_j/w_j was "about 2e-03"
    # (r421 T2: or δ ≤ 1e-3 itself, where w ~ 1e300 makes the sum ~1e-300)
    if delta <= 0 or abs(delta) > (1e-3 * max(abs(s), 1.0) if small else abs(s)):
        return None
    if not np.allclose(g, q / (s + delta), rtol=1e-9, atol=1e-300):
        return None
    return delta


def _nudge_words(args, expected, got) -> str:
    delta = _nudge(args, got)
    total = float(np.sum(np.asarray(args[0], dtype=float) / np.asarray(args[1], dtype=float)))
    # r440 W2: terms scaled by a w (the sum 1e-6 here) hold a smaller ε: the share is theirs too
    share = (
        "" if 0.1 <= abs(total) <= 10 else f", {delta / total:.0e} of Σ λ_j / w_j = {num(total)}"
    )
    return (
        f": they sum to {_their_sum(got)}, not 1: you added a small number (about {delta:.0e}"
        f"{share}) to the sum you divide by (a guard against dividing by 0?); divide by the sum "
        "itself (with every w > 0 and the point in front it is never 0)"
    )


def _nudge_in_w(args, got) -> float | None:
    """δ when ``got`` is λ_i/(w_i + δ), normalised, for one small δ > 0 (a guard against
    dividing by 0 added to each w: ``lam / (w + 1e-6)``), else None (r175 B: told to derive
    again a derivation that was right)."""
    lam, w = (np.asarray(a, dtype=float) for a in args)
    g = np.asarray(got, dtype=float)
    if g.shape != (3,) or not np.isfinite(g).all() or np.ptp(w) == 0:
        return None
    live = (lam != 0) & (g != 0)
    if live.sum() < 2:
        return None
    # two weights with different w: λ_i/g_i ∝ w_i + δ, so their ratio ρ gives δ
    i, j = max(((a, b) for a in np.flatnonzero(live) for b in np.flatnonzero(live) if a < b),
               key=lambda ab: abs(w[ab[0]] - w[ab[1]]))  # fmt: skip
    if w[i] == w[j]:
        return None
    rho = (lam[i] / g[i]) / (lam[j] / g[j])
    if rho == 1:
        return None
    delta = float((w[i] - rho * w[j]) / (rho - 1))
    if not 0 < delta <= 1e-3:
        return None
    return delta if np.allclose(g, _normalised(lam / (w + delta)), rtol=1e-9, atol=0) else None


def _nudge_in_w_words(args, expected, got) -> str:
    lam, w = args
    error = float(np.max(np.abs(np.asarray(got, dtype=float) - expected)))
    return (
        f": you added a small number (about {_nudge_in_w(args, got):.0e}) to each w before "
        "dividing by it (a guard against dividing by 0?): your derivation is right, but the "
        f"ε moves the weights, most where a w is small (here by {error:.1e}); every w here "
        "is positive, so divide by w itself"
    )


#: r175 B: an epsilon in each w, ``lam / (w + 1e-6)`` normalised
def _nudge_fits(find, beyond: bool = False):
    """Does a guard's ε (``find(args, got)``) fit? Beyond a GPU's w it says nothing (r421 T2:
    ``q / (q.sum() + 1e-12)``'s NaN at w = 1e-310 hid its ε elsewhere, and an ε far above
    w = 1e-310 gives the same answer whatever its size, so none is read back there), except
    (``beyond``, r440 M1) where the ε is read back (an ε in each w beside w = 1e-310 and
    w = 1e-3: the smallest w of all was named, "λ1 = 0 … 0 / 0", on a case with neither)."""

    def fits(args, expected, got):
        if _beyond(args[1]):
            if not beyond or near(np.asarray(args[0], dtype=float), got):
                return None  # (λ itself: an ε above every w, or the w clipped, LAM_BEYOND)
            return (find(args, got) is not None) or None
        return find(args, got) is not None

    return fits


def _beyond(w) -> bool:
    """Does a w lie outside float32's range (only a simulator meets it)?"""
    f32 = np.finfo(np.float32)
    w = np.asarray(w, dtype=float)
    return bool(w.min() < f32.tiny or w.max() > f32.max)


NUDGED_W = Mistake("epsilon added to w", _nudge_in_w_words, fits=_nudge_fits(_nudge_in_w, True),
                   parameter=lambda a, e, g: _nudge_in_w(a, g), only_whole=True)  # fmt: skip

#: r153 D3-4: an epsilon in the normaliser, ``q / (q.sum() + 1e-9)``
NUDGED = Mistake("epsilon added to the sum", _nudge_words, fits=_nudge_fits(_nudge),
                 parameter=lambda a, e, g: _nudge(a, g), only_whole=True)  # fmt: skip


def _nudge_scaled(args, got) -> float | None:
    """r440 W2: the ε of ``q / (q.sum() + ε)`` where q_i = λ_i · (w_ref / w_i), w_ref the
    smallest w that weighs (the task's scaling): δ · w_ref, one number on every case."""
    delta = _nudge(args, got, small=False)
    if delta is None:
        return None
    lam, w = (np.asarray(a, dtype=float) for a in args)
    return delta * float(w[lam != 0].min())


def _nudge_scaled_words(args, expected, got) -> str:
    lam, w = (np.asarray(a, dtype=float) for a in args)
    k = int(np.flatnonzero(lam != 0)[np.argmin(w[lam != 0])])
    total = float(np.sum(lam * (w[k] / w)))
    return (
        f": they sum to {_their_sum(got)}, not 1: you added a small number (about "
        f"{_nudge_scaled(args, got):.0e}) to the sum you divide by (a guard against dividing by "
        f"0?), but your terms, scaled by w{k + 1} = {w[k]:.3g}, sum to only {num(total)} here; "
        "divide by the sum itself (with every w > 0 and the point in front it is never 0)"
    )


#: r440 W2: the ε in the normaliser of the right (scaled) terms, one ε in their units
NUDGED_SCALED = Mistake("epsilon added to the sum", _nudge_scaled_words,
                        fits=_nudge_fits(_nudge_scaled),
                        parameter=lambda a, e, g: _nudge_scaled(a, g), only_whole=True)  # fmt: skip


def _tiny_lams(lam) -> np.ndarray:
    lam = np.asarray(lam, dtype=float)
    return (lam != 0) & (np.abs(lam) <= 1e-6)


def _tiny_lam_dropped(lam, w):
    """r440 W1: μ with each tiny λ (0 < |λ| ≤ 1e-6) left out, as a mask ``|λ| > 1e-9`` does."""
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    if not _tiny_lams(lam).any():
        return None
    kept = np.where(_tiny_lams(lam), 0.0, lam)
    return weights_per_row(kept[None], w[None], extrapolate=True)[0]


def _tiny_lam_words(args, expected, got) -> str:
    lam, w = (np.asarray(a, dtype=float) for a in args)
    k = int(np.flatnonzero(_tiny_lams(lam))[0])
    return (
        f": your weight of v{k + 1} is 0, but λ{k + 1} = {lam[k]:.3g} is not 0 (p lies next to "
        f"the edge opposite v{k + 1}, not on it), and beside w{k + 1} = {w[k]:.3g}, the "
        f"smallest w, its term weighs μ{k + 1} = {expected[k]:.3g}: you left out a λ below a "
        "tolerance (a mask |λ| > ε?). Leave out only a λ that is exactly 0"
    )


def _tiny_lam_fits(args, expected, got) -> bool | None:
    """Is the answer μ with the tiny λ left out? Nothing said where there is none, or where
    the answer is right (a mask's ε below this λ: the next case's smaller λ may catch it)."""
    dropped = _tiny_lam_dropped(*args)
    g = np.asarray(got, dtype=float)
    if dropped is None or g.shape != (3,) or not np.isfinite(g).all() or all_close(g, expected):
        return None
    return near(dropped, g)


#: r440 W1: a tiny λ left out (a tolerance in "the vertices that weigh", whatever its ε)
TINY_LAM = Mistake("tiny λ left out", _tiny_lam_words, fits=_tiny_lam_fits)


def _ratio_overflowed(lam, w) -> np.ndarray:
    """The vertices whose λ ≠ 0 and whose ratio w_i / w_ref to the smallest w that weighs
    overflows float64 (r495: scaled by w_i / w_ref, a ratio above 1, their terms were 0)."""
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    m = lam != 0
    with np.errstate(over="ignore"):
        return m & np.isinf(w / w[m].min())


def _ratio_overflow_fits(args, expected, got) -> bool | None:
    """Is the answer μ with the terms of an overflowed ratio above 1 set to 0?"""
    lam, w = (np.asarray(a, dtype=float) for a in args)
    gone = _ratio_overflowed(lam, w)
    g = np.asarray(got, dtype=float)
    if not gone.any() or g.shape != (3,) or not np.isfinite(g).all() or all_close(g, expected):
        return None
    kept = np.where(gone, 0.0, lam)
    if not (kept != 0).any():
        return None
    return near(weights_per_row(kept[None], w[None], extrapolate=True)[0], g)


def _ratio_overflow_words(args, expected, got) -> str:
    lam, w = (np.asarray(a, dtype=float) for a in args)
    k = int(np.flatnonzero(_ratio_overflowed(lam, w))[0])
    ref = float(w[lam != 0].min())
    return (
        f": your weight of v{k + 1} is {num(float(np.asarray(got, float)[k]))}, but its μ{k + 1} "
        f"= {expected[k]:.3g}: the ratio w{k + 1} / w_ref = {w[k]:.3g} / {ref:.3g} to the "
        "smallest w lies beyond float64's largest number, 1.8e308, so a term λ / (w / w_ref) "
        "became λ / inf = 0, though λ · (w_ref / w), a ratio below 1, is a subnormal number "
        "that float64 still holds: scale each term by a ratio ≤ 1 (the smallest w over yours), "
        "never by one above 1"
    )


#: r495: a scale by w_i / w_ref (frexp exponents, or a ratio above 1) lost a term that counts
RATIO_OVERFLOW = Mistake("ratio above 1 overflowed", _ratio_overflow_words,
                         fits=_ratio_overflow_fits)  # fmt: skip


def _float32_error(args, expected, got) -> float | None:
    """The answer's largest error where it is finite weights within float32's rounding of μ
    on a GPU's w (r440 M2, H3: a float64 answer from a float32 step), else None."""
    if _beyond(args[1]) or held_by_precision(expected, got):
        return None  # (float32 numbers returned: the float32 of the checker's own words)
    g = np.asarray(got, dtype=float)
    if g.shape != (3,) or not np.isfinite(g).all():
        return None
    error = float(np.max(np.abs(g - expected)))
    bound = FLOAT32_OPS * FLOAT32_EPS * max(1.0, float(np.abs(expected).max()))
    return error if error <= bound else None


def _float32_step_words(args, expected, got) -> str:
    return (
        f": yours are off by {_float32_error(args, expected, got):.1g}, about float32's rounding "
        "(float32 keeps about 7 significant digits), and your code reads float32: a step of "
        "yours (a ratio of w, a sum) ran in float32, and its rounding stays in the float64 "
        "numbers you return. Compute every step in float64 (plain Python floats or np.float64)"
    )


#: r440 M2, H3: a ratio or the sum computed in float32, returned as float64 (the answer holds
#: numbers float32 does not, so the float32 of :func:`.diagnosis.low_precision_mistake` does
#: not fit): told "turn that around" or "they sum to 0.9999999"
FLOAT32_STEP = Mistake("float32", _float32_step_words, only_whole=True, reads="float32",
                       fits=lambda a, e, g: (None if _beyond(a[1]) else
                                             _float32_error(a, e, g) is not None))  # fmt: skip


def _zero_lam_weight(args, expected, got) -> bool | None:
    lam, g = np.asarray(args[0], dtype=float), np.asarray(got, dtype=float)
    if g.shape != (3,) or not np.isfinite(g).all() or not (lam == 0).any():
        return None
    return bool((g[lam == 0] != 0).any())


def _zero_lam_words(args, expected, got) -> str:
    lam, g = np.asarray(args[0], dtype=float), np.asarray(got, dtype=float)
    k = int(np.flatnonzero((lam == 0) & (g != 0))[0])
    return (
        f": where λ{k + 1} = 0 (p on the edge opposite v{k + 1}) your weight of v{k + 1} is "
        f"{num(float(g[k]))}, not 0: μ_i goes as λ_i / w_i, so it is 0 wherever λ_i is 0, "
        "whatever the w. A number you never computed? (np.divide(..., where=...) without out= "
        "leaves the entries it skips as they were in memory: pass out=np.zeros(3))"
    )


def _unwritten_nan(args, expected, got) -> bool | None:
    """r455 W1: NaN on a GPU's w where some λ is 0: no step overflows there, and the check
    fills freed memory with NaN (:func:`poison_freed_memory`): an entry never written."""
    lam, w = (np.asarray(a, dtype=float) for a in args)
    if _beyond(w) or not (lam == 0).any():
        return None
    return _holds_nan(got)


def _unwritten_words(args, expected, got) -> str:
    lam = np.asarray(args[0], dtype=float)
    k = int(np.flatnonzero(lam == 0)[0])
    return (
        f": on these w no step overflows or divides 0 by 0, but λ{k + 1} = 0 here, and a term "
        f"you never wrote (v{k + 1}'s, skipped because its λ is 0) held NaN, and spread through "
        "the sum: np.divide(..., where=...) without out= (or np.empty) leaves the entries it "
        "skips as they were in memory (zeros on many runs; this check fills freed memory with "
        "NaN so that it shows every time): pass out=np.zeros(3), or set those entries to 0"
    )


SYMPTOMS = (
    Mistake("sum", _sum_words, fits=lambda a, e, g: _sums_to_other_than_1(g), symptom=True),
    # r440 H2: np.divide(..., where=lam != 0) without out=: garbage where λ = 0, the rule said
    Mistake("weight where λ = 0", _zero_lam_words, fits=_zero_lam_weight, symptom=True),
)  # fmt: skip


def draw_weights(ax, case, got):
    """Three groups of bars: λ, the expected μ and yours, and how much yours differ where
    the bars cannot show it (:func:`.drawing.difference_note`)."""
    from .drawing import difference_note

    _, (lam, w), expected = case
    x = np.arange(3)
    artists = list(ax.bar(x - 0.27, lam, width=0.25, color="#c8c8c8", label="screen λ"))
    artists += list(ax.bar(x, expected, width=0.25, color="#2b7bba", label="3-D μ (expected)"))
    if got is not None and np.isfinite(got).all():
        wrong = not all_close(np.asarray(got, dtype=float), expected)
        artists += list(ax.bar(x + 0.27, np.clip(got, -2, 2), width=0.25,
                               color="#d7301f" if wrong else "#7fbf7f", label="yours"))  # fmt: skip
        if wrong:
            artists += difference_note(ax, expected, got, where=(0.02, 0.98))
    elif got is not None:  # r421 T2: NaN or inf (w beyond a GPU's range) drew no bar of yours
        # r429 S1: two lines, clear of the legend on the right ("no bars" ran under it)
        artists.append(ax.text(0.02, 0.96, f"yours: {vec(got)}:\nno bars", transform=ax.transAxes,
                               ha="left", va="top", fontsize="small", color="#d7301f"))  # fmt: skip
    ax.set_xticks(x, [f"v{k + 1}\nw = {w[k]:.3g}" for k in range(3)], fontsize="x-small")
    ax.set_ylabel("weight")
    ax.axhline(0, color="black", linewidth=0.5)
    low, high = ax.get_ylim()  # room above the bars for the legend and the note (r175 D11)
    ax.set_ylim(low, high + 0.6 * (high - low))
    artists.append(ax.legend(fontsize="x-small", loc="upper right"))
    return artists


PERSPECTIVE_WEIGHTS = Exercise(
    "perspective_weights", weights_cases, as_weights, same_weights, explain_weights, _rule,
    [*map(_says_no_nan, [*variant_mistakes(_variants, MISTAKES), *PAIRINGS]), NUDGED,
     NUDGED_SCALED, NUDGED_W,
     *(Mistake(kind, words, fits=_beyond_slip(kind)) for kind, words in BEYOND.items()),
     LAM_BEYOND, NAN_BEYOND, TINY_LAM, RATIO_OVERFLOW, FLOAT32_STEP,
     Mistake("uninitialised memory", _unwritten_words, fits=_unwritten_nan), *SYMPTOMS],
    answers=(PackageAnswer(perspective_weights), PackageAnswer(weights_per_row),
             # r148 D12-5: the last step of the answer, q / Σq, is the package's too
             PackageAnswer(normalised_weights)),
    draw=draw_weights, slow=ONE_POINT, match=match_weights, raised_words=_weights_raised,
    call=call_weights, hints=(
        # r39 03-3: the first wrong try printed the answer the task asks to work out
        ("so the 3-D weights go as λ_i / w_i, not λ_i · w_i", "so work out λ_i from the 3-D "
         "weights μ and the three w (a point's screen x is x/w), then turn that around"),
        ("neither divided by w nor summing to 1", "neither the 3-D weights nor summing to 1"),
        # r46 P1: the unnormalised answer's words gave the sum to divide by
        ("(divide by their sum Σ λ_j / w_j, the interpolated 1/w)", "(by what must they be "
         "divided to sum to 1?)"),
        (" (μ_i ∝ λ_i / w_i, normalised to sum to 1)", ": write λ_i in terms of μ and the three "
         "w, turn that around, and make the weights sum to 1"),
        (" (μ_i ∝ λ_i / w_i; yours already sum to 1)", ": write λ_i in terms of μ and the "
         "three w and turn that around (yours already sum to 1)"),
        # r164 B5: the new words for λ/w² and a weight without its 1/w say the division
        (": the screen position divides by w once", ": write λ_i in terms of μ and the three "
         "w and turn that around (how often does the screen position divide by w?)"),
        ("; every vertex's λ is divided by its own w", "; write λ_i in terms of μ and the three "
         "w: what does each vertex's w do to its weight?"),
        (W_NOT_AFFINE, "is the point's w affine on the screen, as you took it? (write the "
         "screen position as the clip position over w)"),
        (BY_THEIR_SUM, "by what must they be divided to sum to 1?"),
        # r421 T2: the repair of an overflow is the task's reasoning: the hint asks for it
        (ONLY_RATIOS, "Which quantities built from the three w stay finite whatever the w, "
         "and keep at least one term whole?"),
        (". Scale by the smallest w among the vertices whose λ is not 0: that vertex's term "
         "is its λ itself, so the sum cannot underflow to 0", ": which w keeps at least one "
         "term whole?"),
        (RATIO_REPAIR, "Which ratios of w can neither overflow nor all vanish to 0?"),
    ),
)  # fmt: skip
