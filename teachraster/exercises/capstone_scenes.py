"""The built-in scenes as the capstone renders them: the texture scenes made able to tell
a filter's mistakes apart.

The floor's checkerboard is symmetric (its transpose is itself) and its (u, v) stay inside
[0, 1], so a filter that swaps u and v, or clamps where it should repeat, would draw the same
frame. The capstone's floor is tinted by two ramps, red growing from column to column (with u)
and green from row to row (with v), so the transpose shows, and its vertices' (u, v) run from
−¼ to 1¼ (so on screen u crosses 0 and 1 and v crosses 1, and the wrap mode shows: r137
D12-2). The sphere's checkerboard is tinted the same way (r40 12-2: a bilinear that swaps u
and v drew the untinted sphere right).

The grid's triangles all run one way on screen, so a ``covers`` that accepts one winding
drew it right (r148 D12-1): the capstone's grid has every other quad's two triangles listed
in the other order (:func:`both_windings`), so it holds both windings, as its title says.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..pipeline.geometry.mesh import Mesh
from ..pipeline.rendering.scenes import Scene, get_scene

#: The capstone's (u, v) range on the tiled floor: u' = UV_SCALE · u + UV_SHIFT.
UV_SCALE, UV_SHIFT = 1.5, -0.25


def capstone_scene(name: str, tiled: bool = False, tinted: bool = False) -> Scene:
    """Built-in scene ``name``, built afresh (a student's function may write into what it is
    given); ``tinted``: its texture tinted by ramps; ``tiled``: tinted and its (u, v)
    widened."""
    scene = get_scene(name)
    if name == "grid":
        return both_windings(scene)
    if not (tiled or tinted):
        return scene
    tex = np.asarray(scene.texture, dtype=float)
    h, w = tex.shape[:2]
    ramp_x = 0.55 + 0.45 * (np.arange(w) + 0.5) / w  # red grows column by column (with u)
    ramp_y = 0.55 + 0.45 * (np.arange(h) + 0.5) / h  # green grows row by row (with v)
    tinted = tex.copy()
    tinted[..., 0] *= ramp_x[None, :]
    tinted[..., 1] *= ramp_y[:, None]
    attrs = dict(scene.mesh.attrs)
    if tiled:
        attrs["uv"] = attrs["uv"] * UV_SCALE + UV_SHIFT
    mesh = Mesh(scene.mesh.positions, scene.mesh.triangles, attrs)
    return replace(scene, mesh=mesh, texture=tinted)


def both_windings(scene: Scene) -> Scene:
    """``scene`` with the vertex order of every other quad's triangles reversed (a quad is two
    consecutive triangles, in a checkerboard of quads): the same surface, both windings."""
    tris = np.array(scene.mesh.triangles)
    n = int(round(np.sqrt(len(tris) // 2)))  # an n × n grid of quads, two triangles each
    quad = np.arange(len(tris)) // 2
    flip = ((quad // n + quad % n) % 2 == 1) if n * n * 2 == len(tris) else (quad % 2 == 1)
    tris[flip] = tris[flip][:, ::-1]
    mesh = Mesh(scene.mesh.positions, tris, dict(scene.mesh.attrs))
    return replace(scene, mesh=mesh)
