/* AxisStencil.glsl: linear interpolation along one axis of a grid, clamped at its ends or
   wrapping on a periodic axis: the stencil of MAC sampling (MacSampling.glsl) and of the volume
   preview (render_volume.comp). */
#ifndef MODEFLOW_SHADERS_AXIS_STENCIL_GLSL
#define MODEFLOW_SHADERS_AXIS_STENCIL_GLSL

/* Linear interpolation along one axis between positions lo and hi = lo + 1, or a single position
   (hi == lo, f = 0) on a one-point axis. */
struct AxisStencil {
    int lo;
    int hi;
    float f;
};

/* Along an axis with n samples at grid coordinates offset + 0, 1, ..., n - 1, clamped to them,
   or on a periodic axis repeating every n (n - 1 interpolates with 0). The index is clamped as an
   integer too: a diverged run's NaN coordinate makes floor() some undefined value, which must
   still address the buffer (the reference samples it as 0). The wrap is a compare and select,
   not an integer modulo: lavapipe runs both sides of an `if` whichever lanes take it, and has no
   vector integer division, so a modulo here divided lane by lane in every trilinear sample of
   every run, periodic or not (3D MacCormack at 64^3: see SmokeAdvect.glsl). */
AxisStencil axisStencil(float coordinate, float offset, int n, bool periodic) {
    AxisStencil a;
    if (periodic) {
        const float s = mod(coordinate - offset, float(n));  // [0, n], n only by round-off
        const float below = floor(s);
        const int lo = clamp(int(below), 0, n);
        a.lo = lo == n ? 0 : lo;
        a.hi = a.lo + 1 == n ? 0 : a.lo + 1;
        a.f = s - below;
        return a;
    }
    const float s = clamp(coordinate - offset, 0.0, float(n - 1));
    a.lo = clamp(int(floor(s)), 0, max(n - 2, 0));
    a.hi = min(a.lo + 1, n - 1);
    a.f = s - float(a.lo);
    return a;
}

bool isPeriodic(uint periodic, int axis) { return (periodic & (1u << uint(axis))) != 0u; }
/* Whether the air flows through the sides across `axis` (a wind, MacGrid::boundaryBits: bit
   3 + axis): their faces are no walls. */
bool flowsThrough(uint boundary, int axis) { return (boundary & (8u << uint(axis))) != 0u; }

#endif
