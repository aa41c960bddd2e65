"""The house: packages by layer, imports pointing one way, no module hidden by a name.

Layers, lowest first: ``core`` (numpy only) -> ``pipeline`` -> ``study`` -> ``plotting`` ->
``widgets``; ``cli`` and ``exercises`` sit on top. A module may import from its own layer and
the layers below, never above.
"""

from __future__ import annotations

import ast
import importlib
import pkgutil
from pathlib import Path

import pytest

import teachraster

PACKAGE = Path(teachraster.__file__).parent
LAYERS = ["core", "pipeline", "study", "plotting", "widgets", "exercises", "cli"]
#: Modules allowed directly in teachraster/ (besides __init__ and __main__).
MAX_TOP_LEVEL = 12


def _layer(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and parts[1] in LAYERS else None


def _imports(path: Path, module: str):
    """Absolute names of the teachraster modules that ``path`` imports."""
    tree = ast.parse(path.read_text())
    package = module.rsplit(".", 1)[0] if path.name != "__init__.py" else module
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.startswith("teachraster"):
                if node.module is None:  # from . import x, y: modules
                    for alias in node.names:
                        yield node.lineno, f"{target}.{alias.name}"
                else:
                    yield node.lineno, target
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("teachraster"):
                    yield node.lineno, alias.name


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE.parent).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        yield path, ".".join(parts)


def test_imports_point_down_the_layers():
    wrong = []
    for path, module in _modules():
        here = _layer(module)
        if here is None:
            continue
        for line, target in _imports(path, module):
            there = _layer(target)
            if there is not None and LAYERS.index(there) > LAYERS.index(here):
                wrong.append(f"{path.relative_to(PACKAGE.parent)}:{line} ({here}) imports {target}")
    assert not wrong, "upward imports:\n" + "\n".join(wrong)


def test_core_imports_numpy_only():
    """The core layer imports nothing outside the standard library, numpy and itself."""
    allowed = {"numpy", "__future__"}
    wrong = []
    for path, module in _modules():
        if _layer(module) != "core":
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and not node.level:
                names = [node.module or ""]
            for name in names:
                top = name.split(".")[0]
                if top in allowed or top in __import__("sys").stdlib_module_names:
                    continue
                wrong.append(f"{module}: {name}")
    assert not wrong, wrong


def test_few_modules_at_the_top():
    top = [p.name for p in PACKAGE.glob("*.py") if p.name not in ("__init__.py", "__main__.py")]
    assert len(top) <= MAX_TOP_LEVEL, top


#: The pipeline's sub-packages in pipeline order, lowest first: each imports only from itself
#: and those before it (the same rule as the layers, one floor down).
PIPELINE_STAGES = [
    "geometry",
    "rasterization",
    "visibility",
    "planning",
    "texturing",
    "antialiasing",
    "blending",
    "rendering",
    "debugging",
]


def _stage(module: str) -> str | None:
    parts = module.split(".")
    if len(parts) > 2 and parts[1] == "pipeline" and parts[2] in PIPELINE_STAGES:
        return parts[2]
    return None


def test_pipeline_is_grouped_by_stage():
    """No module sits loose in pipeline/: each lives in the sub-package of its stage."""
    loose = [p.name for p in (PACKAGE / "pipeline").glob("*.py") if p.name != "__init__.py"]
    assert not loose, f"modules loose in pipeline/: {loose}"
    groups = sorted(
        p.name for p in (PACKAGE / "pipeline").iterdir() if (p / "__init__.py").exists()
    )
    assert set(groups) <= set(PIPELINE_STAGES), groups


def test_pipeline_stages_import_down_only():
    wrong = []
    for path, module in _modules():
        here = _stage(module)
        if here is None:
            continue
        for line, target in _imports(path, module):
            there = _stage(target)
            if there is None and target.startswith("teachraster.pipeline."):
                wrong.append(f"{module}:{line} imports the flat path {target}")
            elif there is not None and PIPELINE_STAGES.index(there) > PIPELINE_STAGES.index(here):
                wrong.append(f"{module}:{line} ({here}) imports {target} ({there})")
    assert not wrong, "upward imports between pipeline stages:\n" + "\n".join(wrong)


def test_flat_pipeline_paths_still_import():
    """Code written before the grouping keeps working: ``teachraster.pipeline.<module>``."""
    for path, module in _modules():
        if _stage(module) is None or path.name == "__init__.py":
            continue
        flat = "teachraster.pipeline." + module.rsplit(".", 1)[1]
        assert importlib.import_module(flat) is importlib.import_module(module), flat


def _packages():
    yield "teachraster"
    yield from (f"teachraster.{n}" for n in LAYERS)
    yield from (f"teachraster.pipeline.{n}" for n in PIPELINE_STAGES)


@pytest.mark.parametrize("package", list(_packages()))
def test_no_module_is_shadowed_by_a_name(package):
    """``import teachraster.x.y as m`` gives the module, never a function of the same name."""
    try:
        pkg = importlib.import_module(package)
    except ImportError as exc:  # a layer that needs an optional extra, or does not exist yet
        pytest.skip(str(exc))
    if not hasattr(pkg, "__path__"):
        pytest.skip(f"{package} is a module")
    for info in pkgutil.iter_modules(pkg.__path__):
        full = f"{package}.{info.name}"
        try:
            mod = importlib.import_module(full)
        except ImportError:  # optional extras (moderngl, ipywidgets) may be missing
            continue
        # absent is allowed (exercise 11's frames are no attribute of ``ex``, r8 11-3); a
        # name bound to something else is not
        assert getattr(pkg, info.name, mod) is mod, (
            f"{package}.{info.name} is not the module {full}"
        )


def test_no_function_longer_than_100_lines():
    long = []
    for path, module in _modules():
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                n = node.end_lineno - node.lineno + 1
                if n > 100:
                    long.append(f"{module}.{node.name}: {n} lines")
    assert not long, long


def test_no_private_names_imported_across_modules():
    wrong = []
    for path, module in _modules():
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom):
                for alias in node.names:
                    if alias.name.startswith("_") and not alias.name.startswith("__"):
                        wrong.append(f"{module} imports {alias.name} from {node.module}")
                if node.module and any(
                    p.startswith("_") and not p.startswith("__") for p in node.module.split(".")
                ):
                    wrong.append(f"{module} imports from private module {node.module}")
    assert not wrong, wrong
