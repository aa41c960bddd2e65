"""The graphics pipeline as one picture: each stage, what it does, and the lessons that teach it.

Rasterisation (this course) sits between vertex processing, which ends in window coordinates,
and the per-fragment stages. Lesson 00 shows the stages as a clickable map
(:mod:`teachraster.widgets.pipeline_map`, which reads its stages and lessons from here); this
static picture of them is for pages and slides with no kernel (lesson 00 showed both until
review r241 S6: one picture of the same ten stages is enough there).
The stages are drawn in the logical order of the OpenGL and Direct3D pipelines: the fragment
(pixel) shader runs before the per-fragment depth and stencil tests, which run before blending.
*Early-z*, running the depth test and write before the shader, is a conditional bypass a
GPU may take only where the result cannot change: when the shader neither discards, writes
depth nor writes memory (image or buffer stores, atomics: side effects a fragment culled early
would lose). A shader that writes its own depth (``gl_FragDepth``, ``SV_Depth``) needs the late test
(conservative depth excepted); with one that may discard, a GPU may still test early and write
late, once the shader has kept the fragment (GL 4.6 §14.9, §15.2; lessons 05a, 10). The picture draws it as an
optional, dashed depth test between rasterisation and the shader. The stages and their lessons are data
(:data:`PIPELINE_STAGES`), so the notebook's list of links and the picture cannot disagree.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from matplotlib.patches import FancyArrowPatch, FancyBboxPatch, Patch

from .common import fs, lw
from .style import COLORS


@dataclass(frozen=True)
class Stage:
    """One pipeline stage: its name, what it does, the lessons (notebook stems) teaching it."""

    name: str
    what: str
    lessons: tuple[str, ...]
    course: bool = False  # the rasterisation core this course is about


#: The stages in order, with the lessons (notebook file stems) where each is taught.
PIPELINE_STAGES: tuple[Stage, ...] = (
    Stage(
        "vertex processing",
        "vertex shader: object (model) → clip coordinates",
        ("04_perspective_correct_interpolation", "05a_zbuffer"),
    ),  # fmt: skip
    # the stages of lesson 00's clickable map, all of them, so that the two pictures list
    # the same stages (review r157 00-10: this one had 8, the map 10)
    Stage("primitive assembly", "vertices → triangles, in the order given", ("02_half_planes",)),
    # the z range is the API's: GL 4.6 §13.7 (default NEGATIVE_ONE_TO_ONE), D3D11.3 §15.4
    # "0 <= z <= w", Vulkan's z_m = 0 unless depthClipControl's negativeOneToOne
    Stage(
        "clipping",
        "x, y: a guard band far beyond ±w; z: −w (GL) or 0 (D3D, Vulkan) to w",
        ("05a_zbuffer",),
    ),  # fmt: skip
    # its own step, before the viewport (GL 4.6 §13.8: perspective division, then the
    # viewport transformation), as the clickable map of lesson 00 draws it too
    Stage(
        "perspective divide",
        "x, y, z ÷ w → normalised device coordinates",
        ("04_perspective_correct_interpolation", "05a_zbuffer"),
    ),  # fmt: skip
    Stage(
        "viewport", "NDC → window x, y (pixels) and depth", ("05a_zbuffer", "05b_depth_precision")
    ),
    Stage(
        "triangle set-up",
        "edges, facing and culling, bounding box",
        ("01_span_tables", "02_half_planes", "03_barycentric_and_plane_equations"),
    ),  # fmt: skip
    Stage(
        "rasterisation",
        "which pixels, with which λ",
        (
            "01_span_tables",
            "02_half_planes",
            "03_barycentric_and_plane_equations",
            "04_perspective_correct_interpolation",
            "06_what_accuracy_costs",  # prices the set-up, fill and interpolation choices
            "07_hard_cases",
            "08_antialiasing",
            "10_tiles_and_hierarchical_z",
            "12a_lines",
        ),
        course=True,
    ),  # fmt: skip
    Stage("fragment shading", "colour, textures; may discard", ("09_texture_filtering",)),
    Stage(
        "depth test",
        "keep the nearest fragment, write its depth (and stencil)",
        ("05a_zbuffer", "05b_depth_precision", "10_tiles_and_hierarchical_z"),
    ),  # fmt: skip
    Stage("blending", "combine with the image", ("12b_blending",)),
)

#: Early-z: the depth test (the second stage) moved in front of the fragment shader, between
#: rasterisation (the first) and shading. Drawn as an optional, dashed test on that path, not
#: as a path around the shader (review r45, 00: the arrow raster -> depth read as fragments
#: skipping the shader).
EARLY_Z = ("rasterisation", "depth test")

#: The early test's label: early-z (test and write before the shader) only when the shader
#: neither discards, writes depth nor writes memory (side effects; review r58 00-2, as lessons
#: 05a and 10 say); with discard, the test may still run early and the write
#: late (lessons 05a, 10; issue 29, review r52 00-4: the box names its lessons).
EARLY_Z_LABEL = (
    # four lines, in a box of EARLY_Z_ROWS rows (three did not hold it); the dashes say
    # optional. Two statements: "neither discards ... (discard: test early, write late)"
    # read as a contradiction (review r157 00-11)
    "early-z (lessons 05a, 10): depth tested and written\nbefore shading, only if the shader "
    "neither discards,\nwrites depth nor writes memory. If it may discard,\nsome GPUs still "
    "test early and write depth late."
)


def lesson_number(stem: str) -> str:
    """``"05a_zbuffer"`` -> ``"05a"``: the lesson's number as the picture shows it."""
    return stem.split("_", 1)[0]


@dataclass
class PipelineArtists:
    """The boxes, texts and arrows of :func:`plot_pipeline`, one entry per stage."""

    boxes: list = field(default_factory=list)
    texts: list = field(default_factory=list)
    arrows: list = field(default_factory=list)
    legend: object = None
    bypass: object = None


def _early_z_row(names: list[str]) -> int | None:
    """The row (a stage's index) after which the early test gets a row of its own: the
    stage early-z starts from (None when the stages do not include both ends)."""
    if not all(name in names for name in EARLY_Z):
        return None
    return names.index(EARLY_Z[0])


#: The rows the early test's row takes (its four lines need more than a stage's one row).
EARLY_Z_ROWS = 1.4


def _early_z_test(ax, y: float, right: float):
    """The optional early depth test: a dashed box at height ``y`` right of the main arrows,
    dashed arrows in from the stage above and on to the shader below. Returns the first arrow."""
    x0, half = 2.2, EARLY_Z_ROWS / 2  # the stages above and below end 0.34 from their rows
    box = FancyBboxPatch((x0, y - half + 0.1), right - x0, 2 * half - 0.2, boxstyle="round,pad=0.02,rounding_size=0.12",
                         fc="white", ec=COLORS["edge"], lw=lw(0.5), ls="--")  # fmt: skip
    ax.add_patch(box)
    ax.text(x0 + 0.2, y, EARLY_Z_LABEL, fontsize=fs(0.8), va="center", style="italic")
    arrows = []
    above, below = y - half - 0.5 + 0.34, y + half + 0.5 - 0.34  # the neighbours' edges
    for start, end in (((1.6, above), (x0, y - 0.2)), ((x0, y + 0.2), (1.6, below))):
        arrow = FancyArrowPatch(start, end, arrowstyle="-|>", ls="--", mutation_scale=fs(1.0),
                                color=COLORS["edge"], lw=lw(0.5))  # fmt: skip
        ax.add_patch(arrow)
        arrows.append(arrow)
    return arrows[0]


def plot_pipeline(ax, stages: tuple[Stage, ...] = PIPELINE_STAGES) -> PipelineArtists:
    """Draw the stages top to bottom as boxes joined by arrows, each with its lessons.

    One stage per row keeps the picture narrow enough for a notebook column at the classroom
    font size (a left-to-right chain would need twice the width). The stages the course is
    about are filled with the "fill" colour, the others grey; a legend says which is which.
    When both stages of :data:`EARLY_Z` are drawn, a dashed box between rasterisation and
    shading is the optional early depth test (early-z), on the way to the shader, not around
    it: the depth test run before the fragment shader, legal only when that cannot change the
    result.

    Parameters
    ----------
    ax : matplotlib Axes
    stages : sequence of Stage

    Returns
    -------
    PipelineArtists
        ``bypass`` is the dashed arrow into the early depth test (None when the stages do not
        include both ends of :data:`EARLY_Z`).
    """
    out = PipelineArtists()
    early = _early_z_row([s.name for s in stages])
    # the early test takes a row of its own (EARLY_Z_ROWS tall), after the stage ``early``
    rows = [
        i + (EARLY_Z_ROWS if early is not None and i > early else 0) for i in range(len(stages))
    ]
    right = 9.0  # the boxes end here
    ax.set(xlim=(0, 9.1), ylim=(rows[-1] + 0.65, -0.65))
    ax.set_axis_off()
    for i, stage in enumerate(stages):
        k = rows[i]  # the row: below the early test's
        colour = COLORS["fill"] if stage.course else COLORS["rejected"]
        box = FancyBboxPatch((0.05, k - 0.34), right - 0.05, 0.68, boxstyle="round,pad=0.02,rounding_size=0.12",
                             fc=colour, ec=COLORS["edge"], lw=lw(0.5))  # fmt: skip
        ax.add_patch(box)
        out.boxes.append(box)
        lessons = ", ".join(lesson_number(s) for s in stage.lessons)
        out.texts.append(ax.text(0.3, k - 0.08, stage.name, fontsize=fs(1.0), fontweight="bold",
                                 va="center"))  # fmt: skip
        out.texts.append(ax.text(0.3, k + 0.2, stage.what, fontsize=fs(0.8), va="center"))
        # on the name's line, which is short: the line below it has the whole box's width
        out.texts.append(ax.text(right - 0.25, k - 0.08, f"lessons {lessons}" if len(stage.lessons) > 1
                                 else f"lesson {lessons}", fontsize=fs(0.8), ha="right",
                                 va="center", style="italic"))  # fmt: skip
        if i:
            above = rows[i - 1]
            arrow = FancyArrowPatch((1.0, above + 0.34), (1.0, k - 0.34), arrowstyle="-|>",
                                    mutation_scale=fs(1.0), color=COLORS["edge"], lw=lw(0.5))  # fmt: skip
            ax.add_patch(arrow)
            out.arrows.append(arrow)
    out.bypass = None if early is None else _early_z_test(ax, early + 0.5 + EARLY_Z_ROWS / 2, right)
    handles = [Patch(fc=COLORS["fill"], ec=COLORS["edge"], label="this course: rasterisation"),
               Patch(fc=COLORS["rejected"], ec=COLORS["edge"], label="around it")]  # fmt: skip
    out.legend = ax.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 1.0),
                           ncols=2, frameon=False, fontsize=fs(0.8))  # fmt: skip
    return out
