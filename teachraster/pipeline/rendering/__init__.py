"""The pipeline in a row: stage functions, ``render`` of clip-space triangles and of scenes.

Lesson 05a read as code: six stage functions, each returning its data and its plan effect;
the built-in scenes; the painter's algorithm for comparison.
"""
