"""One rule for every llvmpipe cross-check module: skip, saying why, where OpenGL is missing,
unless CI requires it (``TEACHRASTER_REQUIRE_GL``, set by ``.ci/run``), which turns the skip
into a failure."""

from __future__ import annotations

import os

import pytest


def require_gl() -> None:
    """Call at the top of a test module, before importing the GL study modules."""
    if os.environ.get("TEACHRASTER_QUICK"):
        # modules are imported to collect them even when their tests are deselected
        pytest.skip("OpenGL cross-checks are not part of the quick tier", allow_module_level=True)
    required = bool(os.environ.get("TEACHRASTER_REQUIRE_GL"))
    try:
        import moderngl  # noqa: F401
    except ImportError as exc:
        if required:
            raise
        pytest.skip(
            f"OpenGL cross-check needs moderngl (pip install moderngl): {exc}",
            allow_module_level=True,
        )
    from teachraster.study.opengl import gl_available

    ok, why = gl_available()
    if not ok:
        if required:
            raise RuntimeError(f"TEACHRASTER_REQUIRE_GL is set but no OpenGL context: {why}")
        pytest.skip(f"no OpenGL context can be created here: {why}", allow_module_level=True)
