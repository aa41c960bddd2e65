"""Texels, mipmaps, filters and the 2×2-quad derivatives that choose a level.

Lesson 09 (Fatahalian, CMU 15-462 *Texture*): sampling, the mip pyramid, λ, anisotropy and
helper pixels.
"""
