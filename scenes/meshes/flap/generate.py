#!/usr/bin/env python3
"""Writes flap_0001.obj ... flap_0048.obj: a plate 0.4 long (x), 0.5 wide (y) and 0.04 thick (z),
clamped at x = 0 and bending up and down once a second, 24 files a second (scenes/flap_3d.toml).
Every file has the same vertices in the same order, so the runtime takes the plate's velocity from
their motion. Run it from this folder: python3 generate.py"""
import math

LENGTH, WIDTH, THICKNESS = 0.4, 0.5, 0.04
SEGMENTS = 12       # along x
FILES, RATE = 48, 24.0
AMPLITUDE = 0.12    # of the free end


def plate(t):
    bend = AMPLITUDE * math.sin(2.0 * math.pi * t)
    vertices = []
    for i in range(SEGMENTS + 1):
        x = LENGTH * i / SEGMENTS
        z = bend * (x / LENGTH) ** 2
        for y, dz in ((-WIDTH / 2, -THICKNESS / 2), (WIDTH / 2, -THICKNESS / 2),
                      (WIDTH / 2, THICKNESS / 2), (-WIDTH / 2, THICKNESS / 2)):
            vertices.append((x, y, z + dz))
    triangles = []
    for i in range(SEGMENTS):
        a, b = 4 * i, 4 * (i + 1)
        for k in range(4):  # the four sides of the segment, facing out
            k1 = (k + 1) % 4
            triangles.append((a + k, b + k1, b + k))
            triangles.append((a + k, a + k1, b + k1))
    last = 4 * SEGMENTS
    triangles += [(0, 2, 1), (0, 3, 2), (last, last + 1, last + 2), (last, last + 2, last + 3)]
    return vertices, triangles


for n in range(1, FILES + 1):
    vertices, triangles = plate((n - 1) / RATE)
    with open("flap_%04d.obj" % n, "w") as out:
        out.write("# scenes/meshes/flap/generate.py, file %d\n" % n)
        for v in vertices:
            out.write("v %.6f %.6f %.6f\n" % v)
        for t in triangles:
            out.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
