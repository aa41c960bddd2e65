"""Rendering a :class:`~teachraster.pipeline.scenes.Scene`: the convenience on top of ``render``.

It projects the scene's mesh with a camera, hands the clip-space triangles to
:func:`teachraster.pipeline.render_triangles.render` together with *only the attributes the shading uses*
(texture coordinates for a textured scene, colours for a coloured one; normals are never
interpolated, since nothing lights these scenes), and shades the result.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from ..core.validate import check_choice
from .camera import Camera
from .inputs import check_force, check_size
from .render_plan import Effect, Plan
from .render_triangles import Frame
from .render_triangles import render as render_clip
from .scenes import Scene
from .texture import FILTERS, sample


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
    **kwargs,
) -> SceneFrame:
    """Render ``scene`` through ``camera`` (default: the scene's own) and shade it.

    Other keyword arguments (``depth_test``, ``cull``, ``depth_format``, ``interpolation``,
    ``trace``, ``subpixel_bits``) go to :func:`teachraster.pipeline.render_triangles.render`;
    ``max_pixels`` (default 2**28) caps ``width * height`` there too, checked before the
    scene is projected.

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
    check_choice("texture_filter", texture_filter, FILTERS)
    forced = check_force(force)
    mesh = scene.mesh
    names = sorted(mesh.attrs) if "attributes" in forced else list(scene.uses)
    skipped = sorted(set(mesh.attrs) - set(names))
    blocks, layout, start = [], {}, 0
    for name in names:
        corner = mesh.corner(name)
        corner = corner[..., None] if corner.ndim == 2 else corner
        blocks.append(corner)
        layout[name] = slice(start, start + corner.shape[2])
        start += corner.shape[2]
    attrs = np.concatenate(blocks, axis=2) if blocks else None
    clip = camera.clip(mesh.corner_positions(), width / height)
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
    if not names:
        effects = tuple(
            Effect("attributes", False, 0, e.total, e.unit, why) if e.name == "attributes" else e
            for e in effects
        )

    if scene.shading == "texture":
        uv = frame.attrs[..., layout["uv"]]
        image = sample(scene.texture, uv, filter=texture_filter)
    elif scene.shading == "color":
        image = frame.attrs[..., layout["color"]]
    else:
        image = _palette(frame.triangle_id)
    return SceneFrame(
        triangle_id=frame.triangle_id,
        attrs=frame.attrs,
        depth=frame.depth,
        plan=Plan(effects),
        trace=frame.trace,
        image=image,
        layout=layout,
    )


def render(clip_or_scene, *args, **kwargs) -> Frame:
    """``render(clip, width, height, ...)`` or ``render(scene, camera, width, height, ...)``.

    With clip-space triangles this is :func:`teachraster.pipeline.render_triangles.render`; with a
    :class:`~teachraster.pipeline.scenes.Scene` it is :func:`render_scene`.
    """
    if isinstance(clip_or_scene, Scene):
        return render_scene(clip_or_scene, *args, **kwargs)
    return render_clip(clip_or_scene, *args, **kwargs)


render.__doc__ += "\n" + (render_clip.__doc__ or "")
