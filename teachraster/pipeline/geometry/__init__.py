"""What is drawn and where it lands: cameras, meshes, OBJ files, homogeneous clipping and the viewport.

Lesson 05a (clipping plane by plane) and the start of every scene: vertex processing in Ritschel's
*Interpolation and z-buffering* order (transform, clip, divide, viewport).
"""
