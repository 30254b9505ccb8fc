/// @file PeriodicReducedVsFull.cpp
/// `reduced_vs_full`'s `periodic` experiment (seed Fig. 6.12): a band-limited flow on the 2D torus
/// [0, 2π)², every amplitude on the basis's first modes, advanced by reduced runs of more and more
/// modes (closed-form torus bases, their sparse coefficients, the midpoint rule) and by the full
/// spectrum of the same grid (PseudoSpectralEuler.h); the relative L2 and L∞ errors of each run's
/// face velocity against the full run over time, and the vorticity at the end with the seed's
/// fluid markers: two disks near the centre, carried by each run's flow.

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "engine/core/MacSampling.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/run/Backend.h"
#include "tools/validate/PseudoSpectralEuler.h"
#include "tools/validate/Studies.h"
#include "tools/validate/StudyRuns.h"

namespace modeflow::validate {
namespace {

constexpr double kLength = 2.0 * std::numbers::pi;
constexpr double kStep = 0.01;    ///< the reduced runs' midpoint step
constexpr int kFullSubsteps = 2;  ///< RK4 steps of the full run per reduced step
constexpr double kSampleEvery = 0.1;
/// The start's RMS face velocity: about two eddy turnovers in the full run's 12 s (at 1, eight,
/// and every run has left the full one by the end whatever its mode count).
constexpr double kSpeed = 0.25;

std::string torusScene(int cells, int modes) {
    const std::string n = std::to_string(cells), l = std::to_string(kLength);
    return "[grid]\nresolution = [" + n + ", " + n + "]\nbounds_min = [0.0, 0.0]\nbounds_max = [" +
           l + ", " + l +
           "]\nperiodic = [true, true]\n[basis]\nvelocity_modes = " + std::to_string(modes) +
           "\nscalar_modes = 0\n[simulation]\ndt = " + std::to_string(kStep) +
           "\nintegrator = \"midpoint\"\n";
}

/// Random amplitudes on the first `band` modes, falling as 1/κ, none on the uniform flows (κ = 0).
Eigen::VectorXd bandLimitedAmplitudes(const Eigen::VectorXd& kappaSquared, int band) {
    std::mt19937 random(612);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd a = Eigen::VectorXd::Zero(band);
    for (int i = 0; i < band; ++i) {
        const double r = uniform(random);
        if (kappaSquared[i] > 1e-9) a[i] = r / std::sqrt(kappaSquared[i]);
    }
    return a;
}

double rms(const std::vector<double>& u) {
    double sum = 0.0;
    for (const double x : u) sum += x * x;
    return std::sqrt(sum / double(u.size()));
}

/// The discrete vorticity (circulation per cell area around each grid vertex), every `stride`-th
/// vertex per axis, rows by y, to 4 significant digits.
std::vector<double> vorticityPicture(const std::vector<double>& faces, int n, int stride) {
    const double h = kLength / n;
    const auto at = [&](int axis, int x, int y) {
        return faces[std::size_t(axis) * n * n + std::size_t((y + n) % n) * n +
                     std::size_t((x + n) % n)];
    };
    std::vector<double> picture;
    for (int y = 0; y < n; y += stride)
        for (int x = 0; x < n; x += stride)
            picture.push_back(significant(
                (at(1, x, y) - at(1, x - 1, y) - at(0, x, y) + at(0, x, y - 1)) / h, 4));
    return picture;
}

/// The seed's fluid markers (Fig. 6.12): points on a lattice filling two disks near the centre.
constexpr double kMarkerRadius = 0.5, kMarkerOffset = 0.7, kMarkerSpacing = 0.04;

/// Marker points, carried by a run's face velocity sampled every kSampleEvery (Heun's rule on
/// the fields at the two ends of each interval, the same for every run).
struct Markers {
    std::array<std::vector<Vec3>, 2> disks;
    std::vector<double> previous;  ///< the face field at the last sample

    Markers() {
        const double centre = 0.5 * kLength;
        for (int side = 0; side < 2; ++side)
            for (double y = -kMarkerRadius; y <= kMarkerRadius; y += kMarkerSpacing)
                for (double x = -kMarkerRadius; x <= kMarkerRadius; x += kMarkerSpacing)
                    if (x * x + y * y <= kMarkerRadius * kMarkerRadius)
                        disks[side].push_back({centre + (side ? kMarkerOffset : -kMarkerOffset) + x,
                                               centre + y, 0.0});
    }

    void advance(const MacGrid& grid, std::vector<double> field, double dt) {
        if (!previous.empty())
            for (std::vector<Vec3>& points : disks)
                for (Vec3& p : points) {
                    const Vec3 u0 = sampleVelocity<double>(grid, previous, p);
                    const Vec3 ahead{p[0] + dt * u0[0], p[1] + dt * u0[1], 0.0};
                    const Vec3 u1 = sampleVelocity<double>(grid, field, ahead);
                    p[0] += 0.5 * dt * (u0[0] + u1[0]), p[1] += 0.5 * dt * (u0[1] + u1[1]);
                }
        previous = std::move(field);
    }

    /// Each disk's points, wrapped into the torus, as [[x, y], ...] rounded to 1e-4.
    nlohmann::json json() const {
        nlohmann::json out = nlohmann::json::array();
        for (const std::vector<Vec3>& points : disks) {
            nlohmann::json list = nlohmann::json::array();
            for (const Vec3& p : points) {
                const auto wrap = [](double v) {
                    return std::round(1e4 * (v - kLength * std::floor(v / kLength))) / 1e4;
                };
                list.push_back({wrap(p[0]), wrap(p[1])});
            }
            out.push_back(list);
        }
        return out;
    }
};

struct Errors {
    double l2, linf;
};

Errors errorsAgainst(const std::vector<double>& u, const std::vector<double>& full) {
    double difference = 0.0, norm = 0.0, worst = 0.0, peak = 0.0;
    for (std::size_t f = 0; f < u.size(); ++f) {
        difference += (u[f] - full[f]) * (u[f] - full[f]), norm += full[f] * full[f];
        worst = std::max(worst, std::abs(u[f] - full[f])), peak = std::max(peak, std::abs(full[f]));
    }
    return {std::sqrt(difference / norm), worst / peak};
}

struct ReducedRun {
    int modes = 0;
    RunInputs inputs;
    std::unique_ptr<VelocityBasis> basis;
    std::unique_ptr<ModalStepping> stepper;
    std::vector<double> l2, linf, energy;
    Markers markers;
};

}  // namespace

nlohmann::json periodicBandLimited(const StudyOptions& options) {
    const int cells = options.quick ? 64 : 256;
    const std::vector<int> counts =
        options.quick ? std::vector<int>{20, 40, 80, 160} : std::vector<int>{120, 300, 500, 1000};
    const int band = counts.front();
    const double duration = options.quick ? 6.0 : 12.0;
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    std::vector<ReducedRun> runs(counts.size());
    Eigen::VectorXd amplitudes;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        options.note("periodic: " + std::to_string(counts[r]) + " modes of the " +
                     std::to_string(cells) + "² torus");
        runs[r].modes = counts[r];
        runs[r].inputs =
            prepareStudyRun(sceneFromText(torusScene(cells, counts[r]), "reduced_vs_full_torus"),
                            options, RunParts::Dynamics);
        runs[r].basis = std::make_unique<VelocityBasis>(runs[r].inputs.cache);
        if (r == 0) {
            amplitudes = bandLimitedAmplitudes(runs[r].inputs.cache.velocity.eigenvalues, band);
            amplitudes *= kSpeed / rms(reference::reconstructFaceField(*runs[r].basis, amplitudes));
        }
        Eigen::VectorXd v = Eigen::VectorXd::Zero(counts[r]);
        v.head(band) = amplitudes;
        runs[r].stepper = backend.makeModalStepper(runs[r].inputs, Integrator::Midpoint);
        runs[r].stepper->setState(v);
    }
    PseudoSpectralEuler full(cells, kLength);
    full.setFaceVelocity(reference::reconstructFaceField(*runs.front().basis, amplitudes));
    const MacGrid grid = MacGrid::fromSpec(runs.front().inputs.cache.grid);
    Markers fullMarkers;

    std::vector<double> time, fullEnergy;
    const int steps = int(std::lround(duration / kStep)),
              sampleEvery = int(std::lround(kSampleEvery / kStep));
    for (int s = 0; s <= steps; ++s) {
        if (s > 0) {
            for (int sub = 0; sub < kFullSubsteps; ++sub) full.step(kStep / kFullSubsteps);
            for (ReducedRun& run : runs) run.stepper->step(kStep);
        }
        if (s % sampleEvery != 0) continue;
        time.push_back(s * kStep);
        fullEnergy.push_back(full.energy());
        const std::vector<double> reference = full.faceVelocity();
        fullMarkers.advance(grid, reference, kSampleEvery);
        for (ReducedRun& run : runs) {
            const Eigen::VectorXd v = run.stepper->state();
            std::vector<double> u = reference::reconstructFaceField(*run.basis, v);
            const Errors e = errorsAgainst(u, reference);
            run.l2.push_back(e.l2), run.linf.push_back(e.linf),
                run.energy.push_back(0.5 * v.squaredNorm());
            run.markers.advance(grid, std::move(u), kSampleEvery);
        }
        if (s % (10 * sampleEvery) == 0) options.note("periodic: t = " + std::to_string(s * kStep));
    }

    const int stride = std::max(1, cells / 64);
    nlohmann::json result = {
        {"domain", "periodic [0, 2π)²"},
        {"resolution", cells},
        {"band_modes", band},
        {"initial", "random amplitudes ∝ 1/κ on the first " + std::to_string(band) + " modes"},
        {"rms_speed", kSpeed},
        {"full", "pseudo-spectral (2/3 dealiased, RK4), every wave vector of the grid"},
        {"dt", kStep},
        {"time", time},
        {"full_energy", fullEnergy},
        {"picture_stride", stride},
        {"full_vorticity", vorticityPicture(full.faceVelocity(), cells, stride)},
        {"markers_start", Markers().json()},
        {"full_markers", fullMarkers.json()},
        {"runs", nlohmann::json::array()}};
    for (const ReducedRun& run : runs)
        result["runs"].push_back(
            {{"modes", run.modes},
             {"relative_l2", run.l2},
             {"relative_linf", run.linf},
             {"energy", run.energy},
             {"markers", run.markers.json()},
             {"vorticity",
              vorticityPicture(reference::reconstructFaceField(*run.basis, run.stepper->state()),
                               cells, stride)}});
    return result;
}

}  // namespace modeflow::validate
