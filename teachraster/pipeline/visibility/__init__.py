"""Which fragment is seen: depth formats and precision, the z-buffer, hierarchical Z.

Lessons 05a, 05b and 10 (Ritschel, *Interpolation and z-buffering*): window depth and its
storage, the depth test for all fragments at once, Hi-Z tiles that drop hidden work, and
Greene's depth pyramid with its bounding-box test (:mod:`.depth_pyramid`).
"""
