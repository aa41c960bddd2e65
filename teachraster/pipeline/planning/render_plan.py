"""The render plan: which effects a scene needs, whether each ran, for how much, and why.

``render`` simulates only what the scene calls for (perspective correction only where w
differs, clipping only for triangles that cross a plane, the depth test only where
fragments of two triangles land on one pixel, attributes only at visible pixels, culling
only on request) and reports each decision here, so a lesson can print it.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..visibility.hiz_tiles import LINE_COST, MIN_SAVING

#: Effects that ``force=`` can switch on everywhere, for comparison.
FORCEABLE = (
    "clipping",
    "perspective",
    "depth_test",
    "hi_z",
    "attributes",
    "multisampling",
    "derivatives",
)


@dataclass(frozen=True)
class Effect:
    """One effect of the pipeline and what the plan did with it.

    ``count`` of ``total`` ``unit`` (e.g. 3 of 120 triangles) is how much it ran for.
    """

    name: str
    ran: bool
    count: int
    total: int
    unit: str
    why: str
    forced: bool = False

    def __str__(self) -> str:
        state = "forced" if self.forced else ("ran" if self.ran else "skipped")
        # "applied to" so that "skipped, applied to 0 of 12" cannot read as "none skipped"
        amount = f"applied to {self.count:>8,} of {self.total:>9,} {self.unit:<10}"
        return f"{self.name:<13} {state:<7} {amount} {self.why}"


@dataclass(frozen=True)
class Plan:
    """The effects of one render, in pipeline order."""

    effects: tuple[Effect, ...]

    def __getitem__(self, name: str) -> Effect:
        for effect in self.effects:
            if effect.name == name:
                return effect
        raise KeyError(f"no effect {name!r}; effects are {[e.name for e in self.effects]}")

    def __iter__(self):
        return iter(self.effects)

    def __str__(self) -> str:
        return "\n".join(str(effect) for effect in self.effects)


def parse_force(force) -> frozenset[str]:
    """``force`` as a set of effect names: None, "all", one name or an iterable of names."""
    if force is None:
        return frozenset()
    if force == "all":
        return frozenset(FORCEABLE)
    try:
        names = {force} if isinstance(force, str) else set(force)
    except TypeError:
        raise TypeError(
            f"force must be None, 'all', an effect name or names, got {force!r}"
        ) from None
    unknown = names - set(FORCEABLE)
    if unknown:
        raise ValueError(f"force: unknown effect(s) {sorted(unknown)}; choose from {FORCEABLE}")
    return frozenset(names)


# -- the words: why each stage ran or was skipped, one function per effect -----------------------
def clipping_effect(n_in: int, n_depth: int, n_guard: int, n_drop: int, forced: bool) -> Effect:
    """Clipping: ``n_depth`` triangles cut at near/far, ``n_guard`` only at the guard band,
    ``n_drop`` dropped whole, of ``n_in`` input triangles."""
    if n_depth:
        why = f"{n_depth} triangle(s) cross the near or far plane and were cut in clip space"
    else:
        why = "no triangle crosses the near or far plane: nothing to clip"
    if n_guard:
        why += (
            f"; {n_guard} reach far beyond the image and were trimmed at the guard band "
            "(invisible parts only)"
        )
    if n_drop:
        why += f"; {n_drop} lie wholly outside and were dropped"
    if forced:
        why = "every triangle sent through the clipper; " + why
    n_cut = n_depth + n_guard
    return Effect("clipping", bool(n_cut) or forced, n_cut, n_in, "triangles", why, forced)


def culling_effect(cull: str | None, n_culled: int, total: int) -> Effect:
    """Culling: ``n_culled`` of ``total`` triangles removed because ``cull`` asked for it."""
    if cull:
        why = f"cull={cull!r} asked: {n_culled} {cull}-facing triangle(s) removed"
    else:
        why = "not asked (cull=None): both windings are drawn"
    return Effect("culling", cull is not None, n_culled, total, "triangles", why)


def depth_test_effect(depth_test: bool, forced: bool, tested: int, covered: int) -> Effect:
    """The z-buffer: ``tested`` of ``covered`` pixels received fragments of 2+ triangles.

    ``forced`` means every fragment went through the test (only meaningful with the test on).
    """
    if not depth_test:
        why = "off (depth_test=False): later triangles overwrite earlier ones"
        tested = 0
    elif forced:
        why = "every fragment depth-tested against the buffer"
    else:
        why = (
            f"fragments of 2+ triangles land on {tested:,} pixel(s): tested there; "
            f"the other {covered - tested:,} covered pixel(s) hold a single fragment"
        )
    ran = depth_test and (tested > 0 or forced)
    return Effect("depth_test", ran, tested, covered, "pixels", why, forced)


def perspective_effect(
    k: int, n_visible: int, n_persp: int, total: int, interpolation: str, forced: bool
) -> Effect:
    """The divide by w: ``n_persp`` of the ``n_visible`` visible triangles (of ``total``)
    have unequal w and were interpolated perspective-correctly (all when ``forced``)."""
    if k == 0:
        why = "no attributes given: nothing to interpolate"
    elif n_visible == 0:
        why = "no triangle is visible: nothing to interpolate"
    elif interpolation == "affine":
        why = "interpolation='affine' asked: screen-space values, no divide by w"
        n_persp = 0
    elif forced:
        why = "divide by w at every pixel, even where all three w are equal"
    elif n_persp:
        why = (
            f"w differs across the vertices of {n_persp} of the {n_visible} visible "
            "triangle(s): f/w over 1/w there; equal w makes affine interpolation exact elsewhere"
        )
    else:
        why = "every triangle has equal w at its vertices: affine interpolation is exact"
    count = n_persp if k else 0
    return Effect("perspective", k > 0 and n_persp > 0, count, total, "triangles", why, forced)


def attributes_effect(
    k: int, n_shaded: int, n_fragments: int, covered: int, forced: bool
) -> Effect:
    """Attribute interpolation: ``k`` channels at ``n_shaded`` of ``n_fragments`` fragments
    (the ``covered`` visible pixels, or every fragment when ``forced``)."""
    if not k:
        why = "no attributes given"
    elif forced:
        why = f"{k} channel(s) at every fragment, hidden ones included"
    else:
        why = f"{k} channel(s) at the {covered:,} visible pixel(s) only, not at hidden fragments"
    return Effect("attributes", k > 0, n_shaded if k else 0, n_fragments, "fragments", why, forced)


def multisampling_effect(n_samples: int, n_per_sample: int, covered: int, forced: bool) -> Effect:
    """MSAA: ``n_per_sample`` of ``covered`` pixels needed work sample by sample.

    At the others every sample shows the same triangle: it covers the whole pixel and no
    other triangle touches it, or every other one that does is farther over the whole pixel
    (or drawn earlier without the depth test). One answer serves all ``n_samples`` there.
    """
    if forced:
        why = f"every covered pixel resolved sample by sample ({n_samples} samples)"
    else:
        why = (
            f"{n_per_sample:,} pixel(s) are partly covered, or another triangle might be in "
            "front in part of the pixel: "
            "coverage and depth tested and colour stored per sample there, shaded once per "
            f"triangle and pixel; the other "
            f"{covered - n_per_sample:,} show one triangle at every sample (it covers the "
            f"whole pixel and is in front over all of it): one answer for all {n_samples}"
        )
    return Effect("multisampling", True, n_per_sample, covered, "pixels", why, forced)


def count_words(n: int, noun: str) -> str:
    """``n`` and ``noun``, plural unless ``n`` is 1: "21 helper pixels", "1 helper pixel"."""
    return f"{n:,} {noun}{'' if n == 1 else 's'}"


def derivatives_effect(
    mode: str | None,
    n_pixels: int,
    n_visible: int,
    n_quads: int,
    n_helpers: int,
    n_fallback: int,
    forced: bool,
) -> Effect:
    """Quad derivatives: ``mode`` differences at ``n_pixels`` of ``n_visible`` visible pixels,
    from ``n_quads`` (quad, triangle) pairs with ``n_helpers`` helper pixels; ``n_fallback``
    pixels took a difference away from a helper beyond the triangle's horizon."""
    if mode is None:
        why = "not asked (derivatives=False): no quads evaluated"
    else:
        why = (
            f"{mode} differences in {count_words(n_quads, '2x2 quad shading')} (a quad is shaded "
            f"once per triangle it touches), {count_words(n_helpers, 'helper pixel')} evaluated on "
            "their triangle's extrapolated interpolation"
        )
        if n_fallback:
            why += f"; {count_words(n_fallback, 'pixel')} avoided a helper beyond the horizon"
        if forced:
            why = "at every visible pixel; " + why
    ran = mode is not None and n_pixels > 0
    return Effect("derivatives", ran, n_pixels, n_visible, "pixels", why, forced)


def hi_z_effect(depth_test: bool, n_fragments: int, result) -> Effect:
    """Hi-Z: fragments rejected before their depth was interpolated, of all covered
    fragments; ``result`` is the :class:`~teachraster.pipeline.hiz_tiles.HiZTiles` record
    (None with the depth test off)."""
    if not depth_test or result is None:
        why = "off (depth_test=False): nothing is hidden, so nothing is rejected early"
        return Effect("hi_z", False, 0, n_fragments, "fragments", why)
    r, t = result, result.tile
    n_occluded = int((r.occluders > 0).sum())
    tiles = f"{n_occluded:,} {t}x{t} tile(s) covered whole by a triangle"
    if r.skipped == "short lines":
        mean = r.fragments / max(r.raster_lines, 1)
        why = (
            f"{r.fragments:,} fragment(s) on {r.raster_lines:,} raster line(s), "
            f"{mean:.1f} per line: even rejecting them all could not pay for Hi-Z (it needs "
            f"{LINE_COST} per line and {MIN_SAVING:,} in all), not run"
        )
    elif r.skipped == "no occluder":
        why = (
            f"no triangle covers a whole {t}x{t} tile: no tile has a farthest depth to "
            "reject blocks against, Hi-Z not run"
        )
    elif r.skipped == "lone occluders":
        why = f"{tiles}, each by a lone triangle nothing else reaches: nothing to reject"
    elif r.skipped:
        why = (
            f"{tiles}, only {r.layered:,} pixel(s) of occluders behind others: too few, "
            f"against {r.raster_lines:,} raster lines, to pay for comparing the lines with "
            "the tiles, Hi-Z not run"
        )
    else:
        why = (
            f"{tiles}: {r.lines:,} raster line(s) reaching others' tiles compared with the "
            f"tiles' farthest occluder depth, {r.lines_rejected:,} rejected whole, "
            f"{r.blocks_rejected:,} of {r.blocks:,} tile block(s) of the rest; {r.rejected:,} "
            f"fragment(s) dropped before their depth was interpolated, {r.interpolated:,} "
            "interpolated"
        )
        if r.forced:
            why = "every raster line compared; " + why.replace(" reaching others' tiles", "")
    return Effect("hi_z", r.ran, r.rejected, r.fragments, "fragments", why, r.forced)
