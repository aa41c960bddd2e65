"""Rendering a :class:`~teachraster.pipeline.scenes.Scene`: the convenience on top of ``render``.

It projects the scene's mesh with a camera, hands the clip-space triangles to
:func:`teachraster.pipeline.render_triangles.render` together with *only the attributes the shading uses*
(texture coordinates for a textured scene, colours for a coloured one; normals are never
interpolated, since nothing lights these scenes), and shades the result.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from ...core.sample_patterns import is_single
from ...core.snapping import SUBPIXEL_BITS
from ...core.validate import check_choice
from ..geometry.camera import Camera
from ..planning.inputs import check_force, check_size
from ..planning.overrides import check_overrides, rule
from ..planning.render_plan import Effect, Plan, count_words
from ..texturing.quad_derivatives import may_minify
from ..texturing.texture import TEXTURE_FILTERS, sample
from ..texturing.texture_filters import MIPMAP_FILTERS
from .msaa_derivatives import sample_derivatives
from .render_triangles import Frame
from .render_triangles import render as render_clip
from .rule_shading import resolve_by_rule, texture_by_rule
from .scenes import Scene


@dataclass(frozen=True)
class SceneFrame(Frame):
    """A :class:`~teachraster.pipeline.render_triangles.Frame` of a scene, shaded.

    Attributes
    ----------
    image : (H, W, 3) float64
        The shaded colour, NaN where nothing was drawn.
    layout : mapping of name to slice
        Where each interpolated attribute sits in ``attrs``; see :meth:`attr`.
    """

    image: np.ndarray | None = None
    layout: dict = field(default_factory=dict)

    def attr(self, name: str) -> np.ndarray:
        """(H, W, k) values of one interpolated attribute."""
        if name not in self.layout:
            raise KeyError(f"{name!r} was not interpolated; these were: {sorted(self.layout)}")
        return self.attrs[..., self.layout[name]]


def _palette(ids: np.ndarray) -> np.ndarray:
    """A distinct, repeatable colour per triangle id (golden-ratio hues), NaN for -1."""
    hue = (ids * 0.618033988749895) % 1.0
    rgb = 0.55 + 0.4 * np.cos(2 * np.pi * (hue[..., None] + np.array([0.0, 1 / 3, 2 / 3])))
    return np.where((ids >= 0)[..., None], rgb, np.nan)


def render_scene(
    scene: Scene,
    camera: Camera | None = None,
    width: int = 320,
    height: int = 240,
    *,
    texture_filter: str = "nearest",
    force=None,
    max_pixels: int | None = None,
    background=(1.0, 1.0, 1.0),
    **kwargs,
) -> SceneFrame:
    """Render ``scene`` through ``camera`` (default: the scene's own) and shade it.

    Other keyword arguments (``depth_test``, ``cull``, ``depth_format``, ``interpolation``,
    ``trace``, ``subpixel_bits``, ``samples``, ``centroid``) go to
    :func:`teachraster.pipeline.render_triangles.render`; ``max_pixels`` (default 2**28) caps
    ``width * height`` there too, checked before the scene is projected. With ``samples`` > 1
    the image is the MSAA resolve: every sample shows its triangle's colour (shaded once per
    pixel and triangle), and uncovered samples count as ``background`` (default white, the
    figure background an uncovered pixel shows); pixels with no covered sample stay NaN.
    ``overrides`` may also replace the filters and the resolve (:mod:`.rule_shading`).

    ``texture_filter`` is any filter of :func:`teachraster.pipeline.texture.sample`. The
    mipmapped ones need the screen-space derivatives of ``uv``: they are computed from 2×2
    quads only for the triangles the texture may be minified on (the plan's "derivatives"
    effect says how many; ``force="derivatives"`` computes them everywhere, with the same
    image); elsewhere the texture is magnified and level 0 is sampled.
    With ``samples`` > 1 a mipmapped filter gets its footprint as a GPU does under MSAA: 2×2
    quads once per (pixel, triangle) pair a sample shows (:mod:`.msaa_derivatives`).

    >>> from teachraster.pipeline.scenes import get_scene
    >>> frame = render_scene(get_scene("textured_floor"), width=64, height=48)
    >>> frame.image.shape, sorted(frame.layout)
    ((48, 64, 3), ['uv'])
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a teachraster Scene, got {type(scene).__name__}")
    camera = scene.camera if camera is None else camera
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a teachraster Camera, got {type(camera).__name__}")
    width, height, max_pixels = check_size(width, height, max_pixels)
    check_choice("texture_filter", texture_filter, TEXTURE_FILTERS)
    forced = check_force(force)
    overrides = kwargs["overrides"] = check_overrides(kwargs.get("overrides"))
    mesh = scene.mesh
    names = sorted(mesh.attrs) if "attributes" in forced else list(scene.uses)
    skipped = sorted(set(mesh.attrs) - set(names))
    attrs, layout = _corner_attributes(mesh, names)
    clip = camera.clip(mesh.corner_positions(), width / height)
    single = is_single(kwargs.get("samples", 1))
    mipmapped = single and scene.shading == "texture" and texture_filter in MIPMAP_FILTERS
    if mipmapped and "derivatives" not in kwargs:
        kwargs["derivatives"] = True
        kwargs["derivatives_where"] = may_minify(
            clip, mesh.corner("uv"), width, height, np.shape(scene.texture)
        )
    frame = render_clip(
        clip, width, height, attrs=attrs, force=forced, max_pixels=max_pixels, **kwargs
    )

    # Say which attributes were interpolated and which were skipped, and why.
    why = f"interpolated {names or 'nothing'} for shading={scene.shading!r}"
    if skipped:
        why += f"; skipped {skipped}: the shading does not use them"
    effects = tuple(
        replace(e, why=f"{why}; {e.why}") if e.name == "attributes" else e for e in frame.plan
    )
    effects = _derivatives_why(effects, scene, texture_filter, kwargs)
    sample_ddx = sample_ddy = None
    if not single and scene.shading == "texture" and texture_filter in MIPMAP_FILTERS:
        sample_ddx, sample_ddy, effects = _msaa_footprint(frame, clip, attrs, layout, effects,
                                                          kwargs)  # fmt: skip
    if not names:
        effects = tuple(
            Effect("attributes", False, 0, e.total, e.unit, why) if e.name == "attributes" else e
            for e in effects
        )

    if frame.sample_triangle_id is None:
        image = _shade(scene, frame.attrs, frame.triangle_id, layout, texture_filter,
                       frame.ddx, frame.ddy, overrides=overrides)  # fmt: skip
    else:  # MSAA: each sample holds its triangle's colour (shaded once per pixel), resolved
        shading = (layout, texture_filter, sample_ddx, sample_ddy, overrides)
        image = _resolved(scene, frame, shading, background)
    return SceneFrame(
        triangle_id=frame.triangle_id,
        attrs=frame.attrs,
        depth=frame.depth,
        plan=Plan(effects),
        trace=frame.trace,
        sample_triangle_id=frame.sample_triangle_id,
        sample_depth=frame.sample_depth,
        sample_attrs=frame.sample_attrs,
        samples=frame.samples,
        image=image,
        layout=layout,
        ddx=frame.ddx,
        ddy=frame.ddy,
    )


def _resolved(scene, frame, shading, background) -> np.ndarray:
    """The MSAA image: every sample's colour (shaded once per pixel and triangle) resolved,
    by the package or by a caller's rule; NaN where no sample is covered."""
    layout, texture_filter, ddx, ddy, overrides = shading
    colours = _shade(scene, frame.sample_attrs, frame.sample_triangle_id, layout,
                     texture_filter, ddx, ddy, full=False, overrides=overrides)  # fmt: skip
    own = rule(overrides, "resolve")
    if own is None:
        image = frame.resolve(colours, background)
    else:
        image = resolve_by_rule(colours, frame.sample_triangle_id, background, own)
    image[~frame.coverage] = np.nan  # no sample covered: uncovered, as without MSAA
    return image


def _msaa_footprint(frame, clip, attrs, layout, effects, kwargs):
    """Per-sample uv derivatives of a multisampled scene, and the plan with their effect."""
    sample_ddx, sample_ddy, effect = sample_derivatives(
        frame.sample_triangle_id, clip, attrs[..., layout["uv"]],
        kwargs.get("subpixel_bits", SUBPIXEL_BITS),
        kwargs.get("interpolation", "perspective") == "perspective",
    )  # fmt: skip
    return sample_ddx, sample_ddy, (*(e for e in effects if e.name != "derivatives"), effect)


def _corner_attributes(mesh, names):
    """The named attributes at every triangle corner as one (N, 3, k) block, and its layout."""
    blocks, layout, start = [], {}, 0
    for name in names:
        corner = mesh.corner(name)
        corner = corner[..., None] if corner.ndim == 2 else corner
        blocks.append(corner)
        layout[name] = slice(start, start + corner.shape[2])
        start += corner.shape[2]
    return (np.concatenate(blocks, axis=2) if blocks else None), layout


def _texture(texture, uv, texture_filter, ddx=None, ddy=None, overrides=None) -> np.ndarray:
    """The textured image; where a mipmapped filter has no derivatives, level 0 (λ = −∞);
    a caller's "bilinear" or "trilinear" rule (``overrides``) filters pixel by pixel."""
    own = rule(overrides, texture_filter) if texture_filter in ("bilinear", "trilinear") else None
    if own is not None:
        return texture_by_rule(texture, uv, texture_filter, ddx, ddy, own)
    if texture_filter not in MIPMAP_FILTERS:
        return sample(texture, uv, filter=texture_filter)
    if ddx is None:
        zero = np.zeros_like(uv)
        return sample(texture, uv, texture_filter, ddx=zero, ddy=zero)
    # Pixels of triangles the plan found magnified everywhere have no derivatives: a zero
    # footprint samples level 0, exactly what their derivatives would have chosen.
    missing = np.isnan(ddx).any(axis=-1) | np.isnan(ddy).any(axis=-1)
    ddx = np.where(missing[..., None], 0.0, ddx)
    ddy = np.where(missing[..., None], 0.0, ddy)
    return sample(texture, uv, texture_filter, ddx=ddx, ddy=ddy)


def _derivatives_why(effects, scene, texture_filter, kwargs):
    """Say why the scene needed derivatives (or not) in front of the stage's own words."""
    if scene.shading != "texture":
        why = f"shading={scene.shading!r} samples no texture"
    elif texture_filter not in MIPMAP_FILTERS:
        why = f"texture_filter={texture_filter!r} uses no mipmaps: no footprint needed"
    elif kwargs.get("derivatives_where") is not None:
        where = kwargs["derivatives_where"]
        n = int(where.sum())
        why = (
            f"texture_filter={texture_filter!r} uses mipmaps; the texture may be minified on "
            f"{n} of {count_words(len(where), 'triangle')}"
            + ("" if n else ": magnified everywhere, level 0 without derivatives")
        )
    else:
        why = f"derivatives={kwargs.get('derivatives')!r} asked"
    return tuple(
        replace(e, why=f"{why}; {e.why}") if e.name == "derivatives" else e for e in effects
    )


def _shade(scene: Scene, attrs, ids, layout, texture_filter, ddx=None, ddy=None,
           full=True, overrides=None) -> np.ndarray:  # fmt: skip
    """The scene's colour from interpolated ``attrs`` (..., k) and triangle ``ids`` (...);
    ``ddx``/``ddy`` the quad derivatives a mipmapped texture filter needs: of every channel
    (``full``), or of the uv channels only."""
    if scene.shading == "texture":
        uv = layout["uv"]
        if ddx is None:
            return _texture(scene.texture, attrs[..., uv], texture_filter, overrides=overrides)
        if full:
            ddx, ddy = ddx[..., uv], ddy[..., uv]
        return _texture(scene.texture, attrs[..., uv], texture_filter, ddx, ddy, overrides)
    if scene.shading == "color":
        return attrs[..., layout["color"]]
    return _palette(ids)


def render(clip_or_scene, *args, **kwargs) -> Frame:
    """``render(clip, width, height, ...)`` or ``render(scene, camera, width, height, ...)``.

    With clip-space triangles this is :func:`teachraster.pipeline.render_triangles.render`; with a
    :class:`~teachraster.pipeline.scenes.Scene` it is :func:`render_scene`.
    """
    if isinstance(clip_or_scene, Scene):
        return render_scene(clip_or_scene, *args, **kwargs)
    return render_clip(clip_or_scene, *args, **kwargs)


render.__doc__ += "\n" + (render_clip.__doc__ or "")
