"""The study: what accuracy costs, the hard cases, and the check against a real GPU.

Lessons 06 and 07 in code. Nothing here is imported by ``import teachraster``:

- :mod:`.precision`: cheaper and costlier arithmetic for the same half-plane test, and where
  a walk in 32-bit registers goes wrong (lesson 10);
- :mod:`.bench`: the accuracy-vs-time study (``python -m teachraster.study.bench``);
- :mod:`.hardcases`: the catalogue of named hard cases, each with a naive variant;
- :mod:`.antialiasing`: exact pixel areas, the ground truth of the sample-count study, and
  temporal antialiasing's history of jittered frames;
- :mod:`.anisotropic_lod`: Vulkan's and Direct3D's anisotropic level of detail, beside the
  sampler's GL formula (lesson 09);
- :mod:`.exact_spans`: lesson 01's stepped span fills, the exact integer DDA and 16.16 fixed
  point (exercise 2's check counts their use as the package's answer);
- :mod:`.opengl`: the same triangles through OpenGL (Mesa's llvmpipe), for cross-checks;
- :mod:`.opengl_owners`: who owns each pixel of a 2-D mesh in llvmpipe (lesson 07);
- :mod:`.llvmpipe_binner`: llvmpipe's binning choices (32- or 64-bit stepping, the command
  of a small triangle, the row loop over 64×64 tiles) re-enacted for lesson 10.
"""
