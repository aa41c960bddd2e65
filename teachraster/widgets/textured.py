"""``TexturedPlaneViewer``: a checkerboard square, affine vs perspective-correct, tilting away."""

from __future__ import annotations

import math

import ipywidgets as widgets
import numpy as np

from ..core.validate import as_size
from ..pipeline.geometry.camera import Camera
from ..pipeline.rendering.render_scenes import render
from ..pipeline.texturing.texture import checkerboard, sample, texel_error
from ..plotting import ComparisonView, plot_profile
from ..plotting.blitting import MOVING, STILL, LayeredBlit
from ..plotting.common import fs
from ..plotting.images import BEHIND_RENDER
from .common import (
    Shown,
    close_tree,
    fit_width,
    style_context,
    title_html,
)
from .display import (
    COMPARISON_DPI,
    comparison_axes,
    new_figure,
    readable_text,
    resolve_backend,
)
from .dragging import same_or_new
from .live_slider import LiveSlider, info_line, slider_display
from .sprites import ColourBarSprite, text_boxes

#: The picture's alternative text in the page
ALT = "affine and perspective-correct texture mapping and their texel error"

#: Corners of the square in its own plane, (x, y): y = 0 is the hinge (the near edge), y = 1
#: the edge that tilts away; and their texture coordinates (u right, v down the texture, so
#: the far edge is the top row of the checkerboard).
CORNERS = np.array([[-1.0, 1.0], [1.0, 1.0], [1.0, 0.0], [-1.0, 0.0]])
CORNER_UV = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
#: Two triangles sharing the diagonal from the far-left to the near-right corner: affine
#: interpolation maps each triangle with its own affine map, so a checker line, straight on
#: either side, changes direction where it crosses the diagonal (the seam).
TRIANGLES = np.array([[0, 3, 2], [0, 2, 1]])
#: How much of the screen the square may fill, in NDC (a margin all round).
FIT = 0.92


def plane_clip(tilt_deg: float, camera: Camera, aspect: float, *, distance: float = 0.6,
               below: float = 1.5, fit: str = "square") -> np.ndarray:  # fmt: skip
    """(2, 3, 4) clip-space triangles of the square tilted ``tilt_deg`` away from the camera.

    The square (side 2) stands like a wall ``distance`` in front of a camera that looks
    straight ahead (down -z), its bottom edge ``below`` units below the eye. Tilting turns it
    about that bottom edge, the top edge going away: at 0° it faces the camera (every w
    equal), at 90° it lies flat like a floor, its far edge at ``distance + 2``.

    The projection is then zoomed and shifted in screen space so the square fills the
    frame at every tilt: an off-centre frustum (glFrustum with asymmetric bounds), which
    changes x and y but keeps every w, so how strong the perspective is depends only on
    where the square is. ``fit="depth"`` fits the square's near-to-far extent only, from the
    frame's margin at the top (its far edge against the sky) to the frame's bottom edge (its
    near edge): its sides may run off the screen, so a floor seen at a grazing angle fills
    every row below the far edge, the bottom row too (r104 09-7: "click a pixel in the
    floor's nearest row" found the bottom row empty).
    """
    if fit not in ("square", "depth"):
        raise ValueError(f"fit must be 'square' or 'depth', got {fit!r}")
    t = math.radians(tilt_deg)
    x, y = CORNERS[:, 0], 2.0 * CORNERS[:, 1]
    world = np.stack([x, y * math.cos(t) - below, -distance - y * math.sin(t)], axis=1)
    clip = camera.clip(world, aspect)
    ndc = clip[:, :2] / clip[:, 3:]
    lo, hi = ndc.min(axis=0), ndc.max(axis=0)
    centre = (lo + hi) / 2
    if fit == "square":
        scale = 2 * FIT / float(np.max(hi - lo))  # one scale for x and y: squares stay square
    else:  # the far edge (the top) at FIT, the near edge (the bottom) at -1
        scale = (FIT + 1) / float(hi[1] - lo[1])
        centre[1] = hi[1] - FIT / scale
    # x_ndc' = scale * (x_ndc - c)  <=>  x_clip' = scale * (x_clip - c * w)
    clip[:, :2] = scale * (clip[:, :2] - centre * clip[:, 3:])
    return clip[TRIANGLES]


class TexturedPlaneViewer:
    """A textured square tilted away from the camera: affine vs perspective-correct texturing.

    Both images come from :func:`teachraster.pipeline.render_triangles.render` of the same two clip-space triangles,
    once with ``interpolation="affine"`` (screen-space texture coordinates, as early
    software renderers and the PlayStation did) and once ``"perspective"``, then sampled from
    a checkerboard with :func:`teachraster.sample`. With affine coordinates the checker
    lines stay straight inside each triangle (an affine map keeps lines straight) but are
    evenly spaced, and they kink along the diagonal shared by the two triangles; the panel
    measures the difference in texels (:func:`teachraster.texel_error`) and the one beside it
    draws v down the middle column both ways (:func:`teachraster.plotting.plot_profile`).
    At tilt 0 all w are equal and the two agree exactly.

    Parameters
    ----------
    width, height : int
        Image size in pixels.
    tilt : float
        Starting tilt in degrees (0: the square faces the camera like a wall; 90: it lies
        flat like a floor).
    distance : float
        Distance from the camera to the square's near (hinge) edge; the square has side 2.
        Nearer means stronger perspective: w runs from ``distance`` to ``distance + 2`` at
        90°.
    below : float
        How far below the eye the hinge edge is (the floor's depth below the camera).
    checks, texels : int
        Checkerboard squares per side and texture size.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    widget : ipywidgets.VBox
    tilt : LiveSlider
        Degrees the square is tilted away, 0 to 90 (also available as ``depth``).
    view : ComparisonView
        ``view.images`` the two renders, ``view.heatmap`` the texel error.
    affine, perspective : (H, W, 3) arrays
        The two images on show (NaN outside the square).
    error : (H, W) array
        |uv_affine − uv_perspective| in texels.
    maximum : float
        Largest texel error on show.

    Notes
    -----
    While the tilt is dragged in the page, each value is shown as a draft: the images and
    the heatmap exact, without the note at the largest error, and the colour bar only if its
    range was drawn before (kept per range). The release always brings the full picture,
    the same as setting ``tilt.value`` from code.

    Examples
    --------
    >>> viewer = TexturedPlaneViewer(64, 48, tilt=0.0, backend="image")
    >>> float(viewer.maximum) < 1e-9
    True
    >>> viewer.tilt.value = 60.0
    >>> viewer.maximum > 1.0
    True
    >>> viewer.close()
    """

    def __init__(
        self,
        width: int = 160,
        height: int = 120,
        *,
        tilt: float = 60.0,
        distance: float = 0.6,
        below: float = 1.5,
        checks: int = 8,
        texels: int = 64,
        backend: str = "auto",
        style: str | None = None,
    ) -> None:
        width, height = as_size("width", width), as_size("height", height)
        self.width, self.height = width, height
        self.backend = resolve_backend(backend)
        self.texture = checkerboard(checks, texels)
        self.distance, self.below = distance, below
        # Looking straight ahead; plane_clip zooms the view onto the square, so the field of
        # view only needs to be some valid angle.
        self.camera = Camera(eye=(0.0, 0.0, 0.0), target=(0.0, 0.0, -1.0), fov_y=60.0,
                             near=0.05, far=50.0)  # fmt: skip
        self._render(tilt)
        with style_context(style):
            fig = new_figure((10, 4), self.backend, dpi=COMPARISON_DPI)
            # no tick labels on any panel: the titles close above the renders, which take
            # the first row's width (review r219 04-3)
            axes = comparison_axes(fig, height, width, colorbars=(False, True), profile=True,
                                   ticks=False)  # fmt: skip
            self.view = ComparisonView(
                self.affine, self.perspective, axes=axes[:3],
                titles=("affine uv", "perspective-correct uv"), label="|error|",
                # the error's range ends on a round number, so that a new tilt whose maximum
                # rounds to a range drawn before puts the colour bar back from its cache
                # (drawn afresh at every release, it was ~16 ms of a ~35 ms final)
                round_range=True,
            )  # fmt: skip
            # the two renders labelled alike: no pixel ticks on either (review r91 04-E: only
            # "affine uv" had them); the error map has none either
            self.view.axes[0].set(xticks=[], yticks=[], xlabel="", ylabel="")
            for ax in self.view.axes[:2]:  # the square's outline against a tinted ground
                ax.set_facecolor(BEHIND_RENDER)
            for ax in self.view.axes[:3]:  # no column labels to clear: the titles sit close
                ax.set_title(ax.get_title(), y=1.0, pad=fs(0.5))
            if self.view.heatmap.colorbar is not None:
                self.view.heatmap.colorbar.set_label("texels")
            # the heatmap's title states the maximum and its ring marks the pixel; the note
            # beside the ring repeated it over the square (review r58 04-4)
            self.view.heatmap.show_note = False
            self.profile = None
            if axes[3] is not None:
                # v down the middle column: even steps (affine) against bunched ones
                self.profile = plot_profile(
                    axes[3], self.uv_affine[..., 1], self.uv_perspective[..., 1],
                    axis="column", index=width // 2, labels=("affine", "perspective"),
                    value="texture v", guides=[self.view.axes[2]], vlim=(-0.04, 1.04),
                )  # fmt: skip
                # the affine curve dashed, on top: at 0° the two coincide and the perspective
                # curve hid it, so the key named a curve nobody saw (review r91 04-E)
                affine_line, persp_line = self.profile.lines
                affine_line.set_zorder(persp_line.get_zorder() + 0.5)
                affine_line.set_linestyle((0, (4, 2)))
                key = axes[3].get_legend()
                if key is not None:  # its handle is a copy, made before
                    key.legend_handles[0].set_linestyle((0, (4, 2)))
            self._show_error()
            # the colour bar's ticks too (review r9 04 c25: they read 10 px at 1024 px); its
            # sprite is made below, after them
            bar = self.view.heatmap.colorbar
            readable_text([*self.view.axes, axes[3], bar.ax if bar else None],
                          profile=self.profile, texts=[self.view.heatmap.note])  # fmt: skip
            # a new tilt changes the images, the heatmap's title and colour bar: the rest
            # (tick labels, titles) stays in a cached background; the colour bar is drawn
            # last, or put back as it was the last time its range came round
            self._blit = self._edit_blit()
            hm = self.view.heatmap
            self._bar = ColourBarSprite(fig, lambda: hm.image, hm.colorbar)
            self.display = slider_display(
                fig, self.backend, draw=self._draw, drafting=self._drafting, alt=ALT
            )
        self.fig = fig

        # in the page, coalesced: the kernel renders the latest angle, never a queue
        self.tilt = LiveSlider(value=tilt, min=0.0, max=90.0, step=1.0,
                               description="tilt (°)", readout_format=".0f",
                               layout=fit_width(widgets.Layout(width="420px")))  # fmt: skip
        self.depth = self.tilt  # the brief's name for it: how far the plane recedes
        self.tilt.observe(lambda change: self.update(change["new"]), "value")
        self.tilt.on_release(self.update)  # a drag ended on a draft: the full picture
        self.info, info_widgets = info_line(self.display)
        self.info.value = self._info_html()
        title = title_html(
            "Texture mapping a receding square: affine vs perspective-correct",
            "Tilt the square away from the camera and compare the two renders. Below: how "
            "far apart their texture coordinates are, in texels, and the texture's v down the "
            "middle column (dashed), both ways.",
        )
        self.widget = widgets.VBox([title, self.tilt, *info_widgets, self.display.widget])
        if self.backend != "ipympl":
            self.display.ahead(self.tilt, self)  # every tilt drawn while the kernel idles

    def _compute_at(self, tilt: float) -> None:
        self._render(tilt)

    def _render(self, tilt: float) -> None:
        clip = plane_clip(tilt, self.camera, self.width / self.height,
                          distance=self.distance, below=self.below)  # fmt: skip
        uv = np.broadcast_to(CORNER_UV[TRIANGLES], (2, 3, 2))
        self.clip = clip
        out = {}
        for mode in ("affine", "perspective"):
            frame = render(clip, self.width, self.height, attrs=uv, interpolation=mode)
            out[mode] = frame.attrs
        self.uv_affine, self.uv_perspective = out["affine"], out["perspective"]
        # clamped, not repeated: the square's uv run from 0 to 1 exactly, and a pixel whose
        # u is 1.0 wrapped to texel 0, one dark pixel beside the last light check at the
        # square's right edge (review r234 04-S1; GL's REPEAT does the same)
        self.affine = sample(self.texture, self.uv_affine, wrap="clamp")
        self.perspective = sample(self.texture, self.uv_perspective, wrap="clamp")
        self.error = texel_error(self.uv_affine, self.uv_perspective, self.texture.shape)

    def _edit_blit(self) -> LayeredBlit:
        """The images, the heatmap's marked maximum, note and title move; the grids, panel
        titles and frames stay (the colour bar is left to :meth:`_draw`)."""
        view = self.view
        images = [art.image for art in view.images] + [view.heatmap.image]
        still = [g.lines for g in view.grids if g is not None]
        still += [s for ax in view.axes for s in ax.spines.values()]
        hm = view.heatmap
        along = [] if self.profile is None else [*self.profile.guides, self.profile.title.axes]
        return LayeredBlit(view.fig, [(MOVING, images), (STILL, still),
                                      (MOVING, [hm.marker, hm.note, hm.title, *along])])  # fmt: skip

    def _draw(self) -> None:
        """Blit the figure, then the colour bar: drawn, put back from the sprite cache, or
        (in a draft, for a range not seen before) left out."""
        self._blit = same_or_new(self._blit, self._edit_blit())
        hm = self.view.heatmap
        others = [ax.bbox for ax in self.view.axes if ax is not hm.colorbar.ax]
        self._bar.draw(self._blit, draft=self._drafting(),
                       others=others + text_boxes([hm.title, hm.note]))  # fmt: skip

    def _drafting(self) -> bool:
        """True while the tilt is being dragged: a draft leaves out what is slow to draw
        (the note at the largest error, a colour bar for a range not drawn before)."""
        return getattr(self, "tilt", None) is not None and self.tilt.dragging

    def _show_error(self) -> None:
        # The heatmap shows texel error, not the colour difference ComparisonView computes:
        # the same artists, given |error - 0|.
        hm = self.view.heatmap
        if not self._drafting():
            hm.update(self.error, np.zeros_like(self.error))
            return
        # a draft: the image's colours at the new range, the colour bar left as it is
        # (brought up to date by the full picture at the release)
        with self._bar.quietly():
            hm.update(self.error, np.zeros_like(self.error))
        hm.note.set_visible(False)

    @property
    def maximum(self) -> float:
        """Largest texel error on show."""
        return self.view.maximum

    def update(self, tilt: float | None = None) -> None:
        """Render again at ``tilt`` (default: the slider's) and update the figure in place."""
        self._render(self.tilt.value if tilt is None else tilt)
        self._set_artists()
        self.info.value = self._info_html()
        self.display.refresh()

    def _set_artists(self) -> None:
        # the two colour images only: the heatmap shows texel error (_show_error), not the
        # colour difference ComparisonView.update would compute first (a colour bar redraw)
        for art, image in zip(self.view.images, (self.affine, self.perspective)):
            art.update(image)
        if self.profile is not None:
            self.profile.update(self.uv_affine[..., 1], self.uv_perspective[..., 1])
        self._show_error()

    def _info_html(self) -> str:
        w = self.clip[..., 3]
        near, far = float(w.min()), float(w.max())
        m = self.maximum
        # rounded as the heatmap's title rounds it (3 significant digits), and measured
        # against the texture's size: a texel error means little without it (review r58 04-4)
        err = f"{m:.3g} texels" if np.isfinite(m) else "none"
        rows, cols = self.texture.shape[:2]
        return (
            f"w from {near:.2f} (near edge) to {far:.2f} (far edge), ratio {far / near:.2f} · "
            f"largest texture-coordinate error of affine interpolation: <b>{err}</b> "
            f"(the texture is {cols} × {rows} texels)"
        )

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_
    noun = "viewer"  # the stand-in's hint: "No kernel is running this viewer"

    def close(self) -> None:
        """Close every widget of the viewer."""
        self.display.close()
        close_tree(self.widget)
