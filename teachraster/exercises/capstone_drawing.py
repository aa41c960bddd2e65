"""The capstone's three panels: your frame, the package's, and where they differ.

As CS184 and CS248 show a student's render beside the reference with a difference image; the
first differing pixel (or the one asked for) is outlined in all three. matplotlib is imported
only here, when a report is drawn.
"""

from __future__ import annotations

import textwrap

import numpy as np

from .scenes import DIFF_COLOUR, MARK_COLOUR


def picture(spec, frame) -> np.ndarray:
    """(H, W, 3) what the scene looks like (NaN where nothing was drawn)."""
    if spec.glass:
        return np.clip(frame.color[..., :3], 0, 1)
    if spec.tie:  # triangles given in clip space: their colour is their attribute
        return np.clip(frame.attrs[..., :3], 0, 1)
    return np.clip(frame.image, 0, 1)


#: Lesson 11's overlays a scene compares: (the panels' title, what the scale counts).
VIEWS = {"overdraw": ("overdraw", "covers"), "depth_complexity": ("depth passes", "passes")}


def _views(report) -> tuple[np.ndarray, np.ndarray | None, str, str]:
    """(the package's picture, yours or None, the overlay's scale or "", its title): the frames,
    or, where the frames look alike and only an overlay differs (a centre covered twice by
    the same colour; a fragment that passed the depth test and was covered later: r163 12-4),
    that view of lesson 11, so that the panels show the difference."""
    spec = report.spec
    ref = picture(spec, report.reference)
    mine = None if report.mine is None else picture(spec, report.mine)
    kind = next((k for k in spec.compare if k in VIEWS), None)
    if mine is None or kind is None:
        return ref, mine, "", ""
    counts = report.reference.overlay(kind), report.mine.overlay(kind)
    looks_alike = np.array_equal(np.nan_to_num(mine, nan=-1.0), np.nan_to_num(ref, nan=-1.0))
    if not looks_alike or np.array_equal(*counts):
        return ref, mine, "", ""
    from matplotlib import colormaps

    top = max(float(np.max(counts[0])), float(np.max(counts[1])), 1.0)
    ref, mine = (colormaps["viridis"](np.asarray(c, float) / top)[..., :3] for c in counts)
    title, counted = VIEWS[kind]
    return ref, mine, f"{counted}: dark 0 to yellow {top:g}", title


def _axes(axes):
    import matplotlib.pyplot as plt

    if axes is None:
        return list(plt.subplots(1, 3, figsize=(8.8, 3.2), layout="constrained")[1])
    axes = list(np.ravel(axes))
    if len(axes) != 3:
        raise ValueError(f"axes must be three Axes, got {len(axes)}")
    return axes


def draw_capstone(report, axes=None, pixel="first") -> list:
    """Draw ``report`` (a :class:`.capstone_render.CapstoneReport`) on three Axes; returns artists."""
    axes = _axes(axes)
    spec = report.spec
    ref, mine, view, title = _views(report)
    wrong = report.differing_pixels()
    h, w = ref.shape[:2]
    artists = []
    # no frame of yours (a stub, an error): no count (r6: "0 pixel(s) differ" beside it)
    n = len(wrong)
    differ = ("nothing to compare yet" if mine is None else "no pixel differs" if n == 0
              else f"{n} pixel{'s' * (n != 1)} differ{'s' * (n == 1)}")  # fmt: skip
    if view:  # an overlay: short titles, the scale below
        titles = (f"yours ({title})", f"package's ({title})", differ)
        axes[0].set_xlabel(view, fontsize="x-small")
    else:
        # r126 D12-3: "intersecting_triangles: yours" overran its panel and shifted it
        mine_title = f"{spec.name}: yours"
        titles = (mine_title if len(mine_title) <= 24 else f"{spec.name}:\nyours",
                  "the package's", differ)  # fmt: skip
    for ax, title in zip(axes, titles):
        ax.set_title(title, fontsize="small")
        ax.set_xticks([])
        ax.set_yticks([])
    artists += _image(axes[1], ref)
    if mine is None:
        artists += _image(axes[0], np.ones_like(ref))
        why = report.failures[0].explanation if report.failures else "not implemented yet"
        artists.append(axes[0].text(0.5, 0.5, "\n".join(textwrap.wrap(why, 30)[:8]),
                                    transform=axes[0].transAxes, ha="center", va="center",
                                    fontsize="x-small", color=DIFF_COLOUR))  # fmt: skip
    else:
        artists += _image(axes[0], mine)
    grey = np.nan_to_num(ref, nan=1.0).mean(axis=2, keepdims=True) * 0.35 + 0.65
    diff = np.repeat(grey, 3, axis=2)
    if len(wrong):
        diff[wrong[:, 0], wrong[:, 1]] = (0.84, 0.19, 0.12)  # DIFF_COLOUR
    elif mine is not None and spec.contrast is not None:  # yours matches: the section's point
        repaired = report.repaired_pixels()  # from the report: no import back to render
        diff[repaired[:, 0], repaired[:, 1]] = (0.17, 0.48, 0.73)
        k = len(repaired)
        axes[2].set_title(f"no pixel differs; blue: {k}\nwhere {spec.contrast}\nshows "
                          "otherwise", fontsize="small")  # fmt: skip
    artists.append(axes[2].imshow(diff, extent=(0, w, h, 0), interpolation="nearest"))
    key = "red: differs, grey: matches" if len(wrong) else ""
    mark = _mark(report, wrong, pixel)
    if mark is not None:
        r, c = mark
        for ax in axes:
            artists += ax.plot([c, c + 1, c + 1, c, c], [r, r, r + 1, r + 1, r],
                               color=MARK_COLOUR, lw=2)  # fmt: skip
            # r148 D12-12: one pixel of 48 is hard to find: a ring of 2 px around it too
            artists += ax.plot([c - 2, c + 3, c + 3, c - 2, c - 2],
                               [r - 2, r - 2, r + 3, r + 3, r - 2],
                               color=MARK_COLOUR, lw=1.5, clip_on=True)  # fmt: skip
            ax.set_xlim(0, w)
            ax.set_ylim(h, 0)
        key = f"pixel ({r}, {c}) outlined" + (f"\n{key}" if key else "")
    if key:
        axes[2].set_xlabel(key, fontsize="x-small")
    return artists


def _image(ax, rgb):
    h, w = rgb.shape[:2]
    shown = np.where(np.isnan(rgb), 1.0, rgb)
    return [ax.imshow(shown, extent=(0, w, h, 0), interpolation="nearest")]


def _mark(report, wrong, pixel):
    if pixel is None:
        return None
    if isinstance(pixel, str):
        return None if not len(wrong) else (int(wrong[0][0]), int(wrong[0][1]))
    r, c = pixel
    return int(r), int(c)
