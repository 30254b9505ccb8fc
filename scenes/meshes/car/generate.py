#!/usr/bin/env python3
"""Writes car.obj: a car-like solid 0.8 long (x, nose at +x), 0.36 wide (y) and 0.28 high (z), its
origin on the ground under its middle (scenes/leaves_3d.toml): the side profile below, extruded
across y, each side fanned from a point inside, every face facing out. Run it from this folder:
python3 generate.py"""

# The side profile (x, z), counter-clockwise in the (x, z) plane: underside, bumper, hood, windscreen,
# roof, rear window, boot.
PROFILE = [(-0.40, 0.04), (0.40, 0.04), (0.40, 0.12), (0.20, 0.15), (0.05, 0.16),
           (-0.02, 0.28), (-0.22, 0.28), (-0.34, 0.17), (-0.40, 0.15)]
HUB = (0.0, 0.13)  # every profile edge is seen from it: the fans do not fold
HALF_WIDTH = 0.18

n = len(PROFILE)
for k in range(n):
    (ax, az), (bx, bz) = PROFILE[k], PROFILE[(k + 1) % n]
    assert (ax - HUB[0]) * (bz - HUB[1]) - (az - HUB[1]) * (bx - HUB[0]) > 0, "fan folds"

vertices = [(x, y, z) for y in (-HALF_WIDTH, HALF_WIDTH) for (x, z) in PROFILE]
vertices += [(HUB[0], -HALF_WIDTH, HUB[1]), (HUB[0], HALF_WIDTH, HUB[1])]
near, far = 2 * n, 2 * n + 1
triangles = []
for k in range(n):
    k1 = (k + 1) % n
    triangles.append((near, k, k1))          # the -y side, facing -y
    triangles.append((far, n + k1, n + k))   # the +y side, facing +y
    triangles.append((k, n + k1, k1))        # around the profile, facing out
    triangles.append((k, n + k, n + k1))


def signed_volume():
    total = 0.0
    for a, b, c in triangles:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = vertices[a], vertices[b], vertices[c]
        total += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return total / 6.0


assert signed_volume() > 0.0, "faces point in"
with open("car.obj", "w") as out:
    out.write("# scenes/meshes/car/generate.py\n")
    for v in vertices:
        out.write("v %.6f %.6f %.6f\n" % v)
    for t in triangles:
        out.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
