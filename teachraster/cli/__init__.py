"""The ``teachraster`` command: classroom exports of fills, comparisons, scenes and cases.

Imports matplotlib only when a command draws, so ``import teachraster.cli`` stays light.
"""

from .commands import build_parser, main

__all__ = ["build_parser", "main"]
