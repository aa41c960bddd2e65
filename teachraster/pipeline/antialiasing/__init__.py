"""MSAA for whole scenes: per-sample depth and coverage, shading once per pixel.

Lesson 08: the multisampled render, with per-sample work only where a pixel needs it.
"""
