"""Colour output: blend equations, sRGB, and the blended colour buffer.

Lesson 12b: what happens to a fragment's colour after the depth test (the output merger), in
submission order, per pixel or per sample.
"""
