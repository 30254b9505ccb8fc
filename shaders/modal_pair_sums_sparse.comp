#version 450
// modal_pair_sums.comp for sparse coefficients (engine/dynamics/SparseCoefficients.h): rows are
// the pairs k < j with any non-zero, each a run of (i, value) entries, and
//
//     sums(k, j) = sum over the row's entries of value * a_i,  stored as U[k][j]
//     (modal_combine.comp).
//
// Pairs without a row keep the zero their sum was initialized with. One invocation per row,
// grid-stride. Layout (engine/device/DeviceCoefficients::slicedRows), sliced ELLPACK: the rows,
// longest first, in slices of PAIR_TILE_LANES; a slice pads its rows to its longest with (0, 0.0)
// entries and stores texel t (entries 2t, 2t + 1) of each of its rows side by side, so the lanes
// of an 8-wide batch (one slice) read one contiguous run per step and stop together. Every input
// is fetched as texels (TexelAccess.glsl), a_i gathered. Why, measured on lavapipe
// (tools/bench/bench_runtime, 10% density): CSR rows read one float and one index a load, one
// invocation per row, were far slower than Eigen's sparse GEMV (engine/README.md "Speed").
#extension GL_GOOGLE_include_directive : require
#include "ModalStepParams.h"
#include "TexelAccess.glsl"

layout(local_size_x = 64, local_size_x_id = 0) in;

// Per row: k, first texel of its slice, texels per row of the slice, j.
layout(set = 0, binding = 0) uniform usamplerBuffer rows;
// Two (column, value bits) entries a texel.
layout(set = 0, binding = 1) uniform usamplerBuffer entries;
// One value a texel (R32UI): a gathered value is one component, not a texel of four and a select.
layout(set = 0, binding = 2) uniform usamplerBuffer a;
layout(std430, set = 0, binding = 3) buffer Sums { float sums[]; };
layout(push_constant) uniform Push { SparsePairSumsParams params; };

float aAt(uint i) { return uintBitsToFloat(texelFetch(a, int(i)).x); }

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint row = gl_GlobalInvocationID.x; row < params.rowCount; row += stride) {
        const uvec4 record = texelFetch(rows, int(row));
        const uint lane = row % PAIR_TILE_LANES;
        float sum = 0.0;
        for (uint t = 0; t < record.z; ++t) {
            const uvec4 pair = texelFetch(entries, int(record.y + t * PAIR_TILE_LANES + lane));
            sum += uintBitsToFloat(pair.y) * aAt(pair.x) + uintBitsToFloat(pair.w) * aAt(pair.z);
        }
        sums[record.x * params.rowFloats + record.w] = sum;
    }
}
