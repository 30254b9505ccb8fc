/* FaceLocation.glsl: a face number of MacGrid's numbering taken apart, the device twin of
   engine/core/FaceLocation.h. Faces are grouped by normal axis (faceStart1, faceStart2: the
   first normal-y and normal-z faces; in 2D faceStart2 is the total), x fastest inside a group,
   with cells + 1 positions along the normal axis, or cells along a periodic one (bit a of
   `periodic`: axis a wraps, MacGrid::periodic). Also the minimum image of an offset. */
#ifndef MODEFLOW_SHADERS_FACE_LOCATION_GLSL
#define MODEFLOW_SHADERS_FACE_LOCATION_GLSL

#include "LaneDivision.glsl"

uint faceAxis(uint face, uint faceStart1, uint faceStart2) {
    return face >= faceStart2 ? 2u : (face >= faceStart1 ? 1u : 0u);
}

/* Lower-corner position of the normal-`axis` face `local` faces after the first one of its group. */
uvec3 facePosition(uint local, uint axis, uvec3 cells, uint periodic) {
    const uint ex = cells.x + (axis == 0u && (periodic & 1u) == 0u ? 1u : 0u);
    const uint ey = cells.y + (axis == 1u && (periodic & 2u) == 0u ? 1u : 0u);
    // Quotients of at most an axis's positions (quotientOf's bound).
    const uint z = quotientOf(local, ex * ey), inPlane = local - z * ex * ey;
    const uint y = quotientOf(inPlane, ex);
    return uvec3(inPlane - y * ex, y, z);
}

/* The offset d moved by whole box lengths (`box` per axis) along the periodic axes to its
   shortest (MacGrid::minimumImage). */
vec3 minimumImage(vec3 d, vec3 box, uint periodic) {
    for (uint a = 0u; a < 3u; ++a)
        if ((periodic & (1u << a)) != 0u) d[a] -= box[a] * round(d[a] / box[a]);
    return d;
}

#endif
