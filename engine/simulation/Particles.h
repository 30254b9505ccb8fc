#pragma once
/// @file Particles.h
/// The particles a run carries (`[[particles]]`), as both backends report and restore them: one
/// entry per particle in the order they were emitted, which is their id (a particle is never
/// removed, so its id is its place). Positions and velocities in world units (z = 0 in 2D).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace modeflow {

struct Particles {
    std::vector<double> position;   ///< x, y, z per particle
    std::vector<double> velocity;   ///< x, y, z per particle
    std::vector<std::uint8_t> set;  ///< the 0-based `[[particles]]` set each came from

    std::size_t size() const { return set.size(); }
    bool empty() const { return set.empty(); }
};

}  // namespace modeflow
