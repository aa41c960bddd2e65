"""``FootprintExplorer``: a screen pixel and its footprint in texture space, both ways (09).

Fatahalian (CMU 15-462 *Texture*) explains mip-mapping by the footprint: the pixel square
mapped into texture space by the derivatives of (u, v), whose size ρ picks the level
λ = log2 ρ (GL 4.6, eq. 8.7). The kernel renders a checkerboard floor once (uv and the 2 × 2
quad derivatives of every pixel); the page then links the two views: click a screen pixel
and its footprint appears in texture space with λ, the levels chosen and the anisotropic
probes (drawn as the static figure draws them); click a point of the
texture and the pixels whose footprints hold it light up on the screen.

Computed in the page (``static/explore_footprint.js``); λ and the levels are those of
:mod:`teachraster.pipeline.texturing.texture_filters`, the probes and the ellipse those of
:mod:`teachraster.plotting.footprint`, compared by the tests.
"""

from __future__ import annotations

import numpy as np

from ..core.validate import as_float, as_size
from ..pipeline.geometry.camera import Camera
from ..pipeline.rendering.render_scenes import render
from ..pipeline.texturing.mip_pyramid import mipmap
from ..pipeline.texturing.texture import checkerboard, sample
from .explorable import Explorable, esm_source
from .textured import CORNER_UV, TRIANGLES, plane_clip

#: Where the floor lies: its near edge this far ahead of the eye and this far below it, so
#: the eye is low (every pixel's view ray meets the floor at less than 45°, at 27° at the
#: near edge when flat) and the footprint is longer in depth than across at every pixel, and
#: more so with distance, as on lesson 09's big floor. (The 2 x 2 square of the
#: FilterExplorer, lesson 04's defaults 0.6 and 1.5, is seen from above near its near edge:
#: there the footprint is long across.)
FLOOR_DISTANCE, FLOOR_BELOW = 1.2, 0.6


def floor_scene(width: int, height: int, tilt: float, repeats: int, texels: int = 64) -> dict:
    """The data the page needs: the rendered floor, per pixel uv and derivatives (None where
    the floor is not; 8 significant digits), the texture's grey values and its number of
    levels. The floor is :func:`plane_clip`'s square with the eye low above it
    (:data:`FLOOR_DISTANCE`, :data:`FLOOR_BELOW`), its depth filling the frame's height and
    its sides running off the screen."""
    camera = Camera(eye=(0.0, 0.0, 0.0), target=(0.0, 0.0, -1.0), fov_y=60.0, near=0.05,
                    far=50.0)  # fmt: skip
    texture = checkerboard(8, texels)
    clip = plane_clip(tilt, camera, width / height, distance=FLOOR_DISTANCE, below=FLOOR_BELOW,
                      fit="depth")  # fmt: skip
    uv = np.broadcast_to(CORNER_UV[TRIANGLES] * repeats, (2, 3, 2))
    frame = render(clip, width, height, attrs=uv, derivatives=True)
    image = sample(texture, frame.attrs, "trilinear", ddx=frame.ddx, ddy=frame.ddy)
    image = np.where(np.isfinite(image), image, 1.0)  # the sky: white
    covered = frame.coverage.ravel()
    per_pixel = [frame.attrs.reshape(-1, 2), frame.ddx[..., :2].reshape(-1, 2),
                 frame.ddy[..., :2].reshape(-1, 2)]  # fmt: skip
    # 8 significant digits: the picture's precision, half the bytes of a double's 17
    uv_, dx, dy = ([[float(f"{v:.8g}") for v in p] if ok else None
                    for p, ok in zip(a, covered, strict=True)] for a in per_pixel)  # fmt: skip
    return {"width": width, "height": height, "repeats": repeats, "texW": texels,
            "texH": texels, "q": len(mipmap(texture)) - 1, "tilt": tilt,
            "texture": np.round(texture.mean(axis=-1), 4).ravel().tolist(),
            "image": np.round(image.reshape(-1, 3) * 255).astype(int).tolist(),
            "uv": uv_, "ddx": dx, "ddy": dy}  # fmt: skip


class FootprintExplorer(Explorable):
    """A textured floor on the screen beside the same floor in texture space, linked.

    Parameters
    ----------
    width, height : int
        The screen image in pixels (at most 96 x 72: every pixel's data goes to the page).
    tilt : float
        The floor's tilt in degrees (0 faces the camera, 90 lies flat).
    repeats : int
        How often the 64-texel checkerboard repeats across the floor.
    pixel : (row, col), optional
        The pixel whose footprint is shown first (default: the farthest row's, where the
        footprint is longest in depth).

    Attributes
    ----------
    state : dict
        ``pixel`` (row, col), ``point`` (texels, or None), ``view`` and ``follow`` (the
        texture view's window, and whether it zooms to the footprint), as of the page's last
        change.

    Examples
    --------
    >>> ex = FootprintExplorer(32, 24, tilt=75)
    >>> ex.data["q"], len(ex.data["uv"])
    (6, 768)
    """

    _esm = esm_source("explore_footprint")
    noun = "footprint explorer"
    title = "A pixel and its footprint"

    def __init__(self, width: int = 48, height: int = 36, *, tilt: float = 80.0,
                 repeats: int = 2, pixel=None) -> None:  # fmt: skip
        width, height = as_size("width", width), as_size("height", height)
        if width > 96 or height > 72:
            raise ValueError(f"width and height must be at most 96 x 72, got {width}x{height}")
        tilt = as_float("tilt", tilt)
        if not 0.0 <= tilt < 90.0:
            raise ValueError(f"tilt must be in [0, 90) degrees, got {tilt}")
        repeats = as_size("repeats", repeats)
        super().__init__()
        data = floor_scene(width, height, tilt, repeats)
        if pixel is None:  # the farthest covered pixel of the middle column
            col = width // 2
            rows = [r for r in range(height) if data["uv"][r * width + col] is not None]
            pixel = (rows[0] + 1 if rows else 0, col)
        pixel = [int(pixel[0]), int(pixel[1])]
        if not (0 <= pixel[0] < height and 0 <= pixel[1] < width):
            raise ValueError(f"pixel must lie in the {width}x{height} image, got {pixel}")
        data["pixel"] = pixel
        self.data = data
        self.state = {"pixel": pixel, "point": None, "follow": True}
