#pragma once
/// @file InitialConditions.h
/// Modal initial velocities that need no grid: random band-limited fields and explicit
/// amplitudes. (Vortex blobs are projected on the basis by the caller, which has the grid.)
/// Mode indices are 0-based positions in the basis (for a frequency-shaped basis, positions in
/// its list of modes, not numbers in the spectrum).

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace modeflow {

struct RandomVelocitySpec {
    int firstMode = 0;       ///< first excited basis index
    int lastMode = -1;       ///< last excited basis index, inclusive; −1: the last mode
    double energy = 1.0;     ///< ½|v|² of the result
    std::uint64_t seed = 1;  ///< seeds std::mt19937_64
};

/// Independent standard-normal amplitudes on modes [firstMode, lastMode], zero elsewhere, scaled
/// to the requested energy. The normals are drawn by Box–Muller from the raw mt19937_64 stream, so
/// a seed gives the same field with every standard library. Throws modeflow::Error for a band
/// outside [0, modeCount), a negative energy, or one too large (requireRepresentableState).
Eigen::VectorXd randomVelocity(int modeCount, const RandomVelocitySpec& spec);

/// v with v[index] = amplitude for each given pair, zero elsewhere. Throws modeflow::Error for an
/// index outside [0, modeCount) or one given twice, or a state requireRepresentableState refuses.
Eigen::VectorXd modalAmplitudes(int modeCount,
                                const std::vector<std::pair<int, double>>& amplitudes);

/// A state every integrator can step: finite, and with |v|⁴ finite (|v| below about 1e77),
/// because a step takes norms of the quadratic term C·v·v. Checked where initial states are
/// built, so that a huge energy, amplitude or strength is not blamed on dt later.
/// @throw modeflow::Error "<what>: ..." naming the first non-finite mode, or |v|.
void requireRepresentableState(const Eigen::VectorXd& state, const std::string& what);

}  // namespace modeflow
