#include "precompute/closedform/ClosedFormCoefficients.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/PackedLayout.h"

namespace modeflow {
namespace {

/// A mode's factors per axis, as the entries use them.
struct ModeFactors {
    std::array<int, 3> wave{0, 0, 0};
    std::array<int, 3> shift{0, 0, 0};
    std::array<double, 3> amplitude{0.0, 0.0, 0.0};
    std::array<double, 3> sigma{0.0, 0.0, 0.0};  ///< (2/h) sin(θ/2)
    std::array<double, 3> gamma{1.0, 1.0, 1.0};  ///< cos(θ/2)
    double largestAmplitude = 0.0;               ///< max |amplitude_a|
    double largestSigma = 0.0;                   ///< max σ_a
};

int cosineOfQuarterTurns(int q) {
    q = ((q % 4) + 4) % 4;
    return q == 0 ? 1 : (q == 2 ? -1 : 0);
}

/// One axis of the grid: its cell count and the period of its wave numbers (2n on a wall: the
/// sums are half of full-period ones; n on a periodic axis).
struct Axis {
    int n = 1;
    int period = 2;
};

/// (4/n) Σ_x g1 g2 g3 over the positions of one axis (whole, or half when `half`), g_t = cos or
/// sin (sine_t) of θ_t x + φ_t: an integer from −4 to 4 (see the header).
int tripleSum(const Axis& axis, const ModeFactors& m1, bool sine1, const ModeFactors& m2,
              bool sine2, const ModeFactors& m3, bool sine3, int a, bool half) {
    const int q1 = m1.shift[a] - sine1, q2 = m2.shift[a] - sine2, q3 = m3.shift[a] - sine3;
    int total = 0;
    for (int e2 = -1; e2 <= 1; e2 += 2)
        for (int e3 = -1; e3 <= 1; e3 += 2) {
            const int m = m1.wave[a] + e2 * m2.wave[a] + e3 * m3.wave[a];
            if (m % axis.period != 0) continue;
            total +=
                cosineOfQuarterTurns(q1 + e2 * q2 + e3 * q3 + (half ? 2 * (m / axis.period) : 0));
        }
    return total;
}

/// Where the assembler puts entries: counted only, then written in place.
struct Counter {
    std::size_t count = 0;
    void push(int, int, int, double) { ++count; }
};

struct Filler {
    BasisCache::Coefficients& out;
    std::size_t at;
    void push(int k, int i, int j, double value) {
        out.k[at] = k;
        out.i[at] = i;
        out.j[at] = j;
        out.value[at] = value;
        ++at;
    }
};

class Assembler {
public:
    Assembler(const GridSpec& grid, const std::vector<SeparableMode>& modes) : mDim(grid.dim) {
        mVolume = 1.0;
        for (int a = 0; a < mDim; ++a) {
            mVolume *= grid.spacing(a);
            mPositions *= grid.resolution[a];
            mAxes[a] = {grid.resolution[a], (grid.isPeriodic(a) ? 1 : 2) * grid.resolution[a]};
        }
        for (const SeparableMode& s : modes) {
            ModeFactors f;
            for (int a = 0; a < mDim; ++a) {
                f.wave[a] = s.wave[a];
                f.shift[a] = s.shift[a];
                f.amplitude[a] = s.amplitude[a];
                f.sigma[a] = axisSigma(grid, a, s.wave[a]);
                const double theta =
                    (grid.isPeriodic(a) ? 2.0 : 1.0) * M_PI * s.wave[a] / grid.resolution[a];
                f.gamma[a] = std::cos(0.5 * theta);
                f.largestAmplitude = std::max(f.largestAmplitude, std::abs(f.amplitude[a]));
                f.largestSigma = std::max(f.largestSigma, f.sigma[a]);
            }
            mModes.push_back(f);
        }
        groupByWaveVector();
    }

    /// Every entry in a fixed order (by first group), whatever the threads did: counted per first
    /// group, then written in place, so the memory is the entries' alone (a few GB at N = 10 000).
    void run(BasisCache::Coefficients& c) const {
        std::vector<std::size_t> offsets(mGroups.size() + 1, 0);
#pragma omp parallel for schedule(dynamic)
        for (std::size_t g = 0; g < mGroups.size(); ++g) {
            Counter counter;
            for (std::size_t h = g; h < mGroups.size(); ++h) pairOfGroups(g, h, counter);
            offsets[g + 1] = counter.count;
        }
        for (std::size_t g = 0; g < mGroups.size(); ++g) offsets[g + 1] += offsets[g];
        const std::size_t total = offsets.back();
        c.k.resize(total);
        c.i.resize(total);
        c.j.resize(total);
        c.value.resize(total);
#pragma omp parallel for schedule(dynamic)
        for (std::size_t g = 0; g < mGroups.size(); ++g) {
            Filler filler{c, offsets[g]};
            for (std::size_t h = g; h < mGroups.size(); ++h) pairOfGroups(g, h, filler);
        }
    }

private:
    void groupByWaveVector() {
        for (const ModeFactors& m : mModes)
            for (int a = 0; a < mDim; ++a) mLargest[a] = std::max(mLargest[a], m.wave[a]);
        std::size_t size = 1;
        for (int a = 0; a < 3; ++a) size *= std::size_t(mLargest[a] + 1);
        mGroupOf.assign(size, -1);
        for (std::size_t m = 0; m < mModes.size(); ++m) {
            int& g = mGroupOf[slot(mModes[m].wave)];
            if (g < 0) {
                g = int(mGroups.size());
                mGroups.emplace_back();
            }
            mGroups[std::size_t(g)].push_back(int(m));
        }
    }

    std::size_t slot(const std::array<int, 3>& wave) const {
        return (std::size_t(wave[2]) * std::size_t(mLargest[1] + 1) + std::size_t(wave[1])) *
                   std::size_t(mLargest[0] + 1) +
               std::size_t(wave[0]);
    }

    /// Every C[k][i][j] with k, j from groups g and h (k ≠ j) and i from a group that the
    /// selection rule allows.
    template <typename Sink>
    void pairOfGroups(std::size_t g, std::size_t h, Sink& out) const {
        const ModeFactors& first = mModes[std::size_t(mGroups[g].front())];
        const ModeFactors& second = mModes[std::size_t(mGroups[h].front())];
        // Per axis: the wave numbers ±l_k ± l_j modulo the period that the basis holds.
        std::array<std::array<int, 4>, 3> third{};
        std::array<int, 3> count{1, 1, 1};
        for (int a = 0; a < mDim; ++a) {
            count[a] = 0;
            const int p = mAxes[a].period;
            for (int v : {first.wave[a] + second.wave[a], first.wave[a] - second.wave[a],
                          second.wave[a] - first.wave[a], -first.wave[a] - second.wave[a]}) {
                const int r = ((v % p) + p) % p;
                if (r > mLargest[a]) continue;
                if (std::find(third[a].begin(), third[a].begin() + count[a], r) !=
                    third[a].begin() + count[a])
                    continue;
                third[a][std::size_t(count[a]++)] = r;
            }
        }
        for (int x = 0; x < count[0]; ++x)
            for (int y = 0; y < count[1]; ++y)
                for (int z = 0; z < count[2]; ++z) {
                    const int gi =
                        mGroupOf[slot({third[0][std::size_t(x)], third[1][std::size_t(y)],
                                       third[2][std::size_t(z)]})];
                    if (gi < 0) continue;
                    for (int p : mGroups[g])
                        for (int q : mGroups[h]) {
                            if (g == h && q <= p) continue;
                            const int k = std::min(p, q), j = std::max(p, q);
                            for (int i : mGroups[std::size_t(gi)]) add(k, i, j, out);
                        }
                }
    }

    template <typename Sink>
    void add(int k, int i, int j, Sink& out) const {
        const ModeFactors& mk = mModes[std::size_t(k)];
        const ModeFactors& mi = mModes[std::size_t(i)];
        const ModeFactors& mj = mModes[std::size_t(j)];
        double value = 0.0;
        for (int t = 0; t < (mDim == 3 ? 3 : 1); ++t) {
            const int a = mDim == 3 ? t : 2, b = (a + 1) % 3, c = (a + 2) % 3;
            const double w = mi.amplitude[b] * mi.sigma[c] - mi.amplitude[c] * mi.sigma[b];
            if (w == 0.0) continue;
            double along = 1.0;
            if (mDim == 3) {
                const int s = tripleSum(mAxes[a], mi, false, mk, false, mj, false, a, true);
                if (s == 0) continue;
                along = 0.25 * mAxes[a].n * s;
            }
            const double scale = mVolume * w * along * 0.0625 * mAxes[b].n * mAxes[c].n;
            const double c1 = mk.amplitude[b] * mk.gamma[c] * mj.amplitude[c] * mj.gamma[b];
            const double c2 = mk.amplitude[c] * mk.gamma[b] * mj.amplitude[b] * mj.gamma[c];
            double x1 = 0.0, x2 = 0.0;
            if (c1 != 0.0)
                x1 = scale * c1 * tripleSum(mAxes[b], mi, true, mk, true, mj, false, b, false) *
                     tripleSum(mAxes[c], mi, true, mk, false, mj, true, c, false);
            if (c2 != 0.0)
                x2 = scale * c2 * tripleSum(mAxes[b], mi, true, mk, false, mj, true, b, false) *
                     tripleSum(mAxes[c], mi, true, mk, true, mj, false, c, false);
            value += x1 - x2;
        }
        // Terms that cancel exactly (in ω: A ⟂ σ) leave round-off; the quadrature's storage drops
        // it too. The scale bounds |C| for these three modes: each 1-D sum is at most n.
        const double bound = 2.0 * mVolume * mPositions * mi.largestAmplitude * mi.largestSigma *
                             mk.largestAmplitude * mj.largestAmplitude;
        if (!(std::abs(value) > 1e-12 * bound)) return;
        out.push(k, i, j, value);
    }

    int mDim;
    double mVolume = 1.0;
    double mPositions = 1.0;  ///< Π n_a
    std::array<Axis, 3> mAxes{};
    std::vector<ModeFactors> mModes;
    std::array<int, 3> mLargest{0, 0, 0};
    std::vector<int> mGroupOf;              ///< wave vector slot → group, or −1
    std::vector<std::vector<int>> mGroups;  ///< modes sharing a wave vector
};

}  // namespace

double estimatedClosedFormNonZeros(int dim, int modes) {
    const double n = std::max(modes, 1);
    const double perSquare = dim == 3 ? std::max(1.5, 2.35 + 0.55 * std::log10(n / 1000.0)) : 1.2;
    return perSquare * n * n;
}

BasisCache::Coefficients assembleClosedFormCoefficients(const GridSpec& grid,
                                                        const std::vector<SeparableMode>& modes) {
    BasisCache::Coefficients c;
    c.storage = BasisCache::Coefficients::Storage::Sparse;
    Assembler(grid, modes).run(c);
    const std::size_t stored = packedSize(modes.size());
    c.density = stored == 0 ? 0.0 : double(c.value.size()) / double(stored);
    return c;
}

}  // namespace modeflow
