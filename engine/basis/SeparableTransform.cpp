#include "engine/basis/SeparableTransform.h"

#include <algorithm>
#include <complex>
#include <string>

#include <fftw3.h>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/format/SeparableModes.h"

namespace modeflow {

namespace {

enum class AxisKind {
    Unused,        ///< an axis the grid does not have: one slot, one position, factor 1
    WallCosine,    ///< cos(πl(i+½)/n) at the n cell centres: REDFT01 / REDFT10
    WallSine,      ///< sin(πlx/n) at the n − 1 interior faces: RODFT00
    PeriodicWave,  ///< cos(2πl(x+o)/n + phase) at n positions: HC2R / R2HC with twiddles
};

}  // namespace

/// One axis of one component, in one direction: a batch of 1-D transforms over every line of the
/// tensor along that axis, written out with the axes rotated (the next axis fastest), so that
/// three passes bring the tensor back to x fastest.
struct SeparableTransform::Pass {
    AxisKind kind = AxisKind::Unused;
    bool synthesis = true;
    int slots = 1;      ///< K: coefficients per line
    int positions = 1;  ///< P: grid positions per line
    int length = 1;     ///< the FFT's length
    std::int64_t lines = 0;
    double* in = nullptr;
    double* out = nullptr;
    fftw_plan plan = nullptr;
    std::vector<std::complex<double>> twiddle;  ///< periodic: z per slot (see run())

    ~Pass() {
        if (plan) fftw_destroy_plan(plan);
        fftw_free(in);
        fftw_free(out);
    }

    /// `input` has `lines` lines of inLength values (fastest), D1 × D2 of them; `output` gets
    /// (D1 fastest, D2, outLength).
    void run(const std::vector<double>& input, std::int64_t d1, std::int64_t d2,
             std::vector<double>& output) const {
        const int inLength = synthesis ? slots : positions,
                  outLength = synthesis ? positions : slots;
        output.assign(std::size_t(std::int64_t(outLength) * d1 * d2), 0.0);
        if (kind == AxisKind::Unused) {
            std::copy(input.begin(), input.end(), output.begin());
            return;
        }
        for (std::int64_t t = 0; t < lines; ++t) {
            const double* line = input.data() + t * inLength;
            double* buffer = in + t * length;
            if (!synthesis) {
                std::copy(line, line + positions, buffer);
                continue;
            }
            std::fill(buffer, buffer + length, 0.0);
            switch (kind) {
                case AxisKind::WallCosine:  // y_i = X_0 + 2 Σ_{l≥1} X_l cos(πl(i+½)/n)
                    for (int l = 0; l < slots; ++l) buffer[l] = (l == 0 ? 1.0 : 0.5) * line[l];
                    break;
                case AxisKind::WallSine:  // y_j = 2 Σ_k X_k sin(π(j+1)(k+1)/n), x = j + 1, l = k +
                                          // 1
                    for (int l = 1; l < slots; ++l) buffer[l - 1] = 0.5 * line[l];
                    break;
                default: {
                    // y_x = Σ_l Re(X_l e^{iθ_l x}), X_l = Σ_phase c z: halfcomplex r_l = Re X/2,
                    // i_l = Im X/2 (HC2R doubles them), r_0 and r_{n/2} = Re X.
                    for (int l = 0; 2 * l < slots; ++l) {
                        const std::complex<double> x =
                            line[2 * l] * twiddle[std::size_t(2 * l)] +
                            line[2 * l + 1] * twiddle[std::size_t(2 * l + 1)];
                        if (l == 0 || 2 * l == length) {
                            buffer[l] = x.real();
                        } else {
                            buffer[l] = 0.5 * x.real();
                            buffer[length - l] = 0.5 * x.imag();
                        }
                    }
                }
            }
        }
        fftw_execute(plan);
        for (std::int64_t t = 0; t < lines; ++t) {
            const std::int64_t i1 = t % d1, i2 = t / d1;
            const double* buffer = out + t * length;
            auto at = [&](int q) -> double& {
                return output[std::size_t((q * d2 + i2) * d1 + i1)];
            };
            if (synthesis) {
                for (int q = 0; q < positions; ++q) at(q) = buffer[q];
                continue;
            }
            switch (kind) {
                case AxisKind::WallCosine:  // Y_l = 2 Σ_i y_i cos(πl(i+½)/n)
                    for (int l = 0; l < slots; ++l) at(l) = 0.5 * buffer[l];
                    break;
                case AxisKind::WallSine:
                    for (int l = 1; l < slots; ++l) at(l) = 0.5 * buffer[l - 1];
                    break;
                default:
                    // Y_l = Σ_x y_x e^{−iθ_l x}; the transpose of Re(c z e^{iθx}) is Re(z conj Y).
                    for (int l = 0; 2 * l < slots; ++l) {
                        const bool real = l == 0 || 2 * l == length;
                        const std::complex<double> y(buffer[l], real ? 0.0 : buffer[length - l]);
                        for (int phase = 0; phase < 2; ++phase) {
                            const std::complex<double> z = twiddle[std::size_t(2 * l + phase)];
                            at(2 * l + phase) = z.real() * y.real() + z.imag() * y.imag();
                        }
                    }
            }
        }
    }
};

namespace {

/// Where a pass of `normal`'s component along `axis` starts and ends (slots, positions) and how
/// many lines it transforms: synthesis goes x, y, z from slots to positions, analysis x, y, z
/// from positions to slots.
std::int64_t linesOf(const std::array<int, 3>& slots, const std::array<int, 3>& positions, int axis,
                     bool synthesis) {
    if (synthesis) {
        // Axes before `axis` are positions by now, those after still slots.
        std::int64_t lines = 1;
        for (int b = 0; b < 3; ++b)
            if (b != axis) lines *= b < axis ? positions[std::size_t(b)] : slots[std::size_t(b)];
        return lines;
    }
    std::int64_t lines = 1;
    for (int b = 0; b < 3; ++b)
        if (b != axis) lines *= b < axis ? slots[std::size_t(b)] : positions[std::size_t(b)];
    return lines;
}

}  // namespace

SeparableTransform::SeparableTransform(const BasisCache& cache)
    : mGrid(cache.grid), mModes(cache.velocity.separable) {
    if (cache.velocity.source != BasisSource::ClosedForm)
        throw Error("separable transform: the velocity basis is not closed form");
    if (cache.faces != wholeBoxFaces(mGrid))
        throw Error(
            "separable transform: the velocity DOFs are not the faces of the whole grid box");
    mDofCount = std::int64_t(cache.faces.size());
    const MacGrid mac = MacGrid::fromSpec(mGrid);
    std::array<int, 3> band{0, 0, 0};
    for (const SeparableMode& m : mModes)
        for (int a = 0; a < mGrid.dim; ++a)
            band[std::size_t(a)] = std::max(band[std::size_t(a)], m.wave[std::size_t(a)]);
    for (int a = 0; a < mGrid.dim; ++a) {
        mSlots[std::size_t(a)] = (mGrid.isPeriodic(a) ? 2 : 1) * (band[std::size_t(a)] + 1);
        mArea[std::size_t(a)] = mac.faceArea(a);
    }
    std::int64_t start = 0;
    for (int normal = 0; normal < mGrid.dim; ++normal) {
        mDofStart[std::size_t(normal)] = start;
        std::array<int, 3> positions{};
        for (int a = 0; a < 3; ++a) positions[std::size_t(a)] = positionCount(normal, a);
        start += std::int64_t(positions[0]) * positions[1] * positions[2];
        for (int axis = 0; axis < 3; ++axis)
            for (bool synthesis : {true, false}) {
                auto pass = std::make_unique<Pass>();
                pass->synthesis = synthesis;
                pass->slots = mSlots[std::size_t(axis)];
                pass->positions = positions[std::size_t(axis)];
                pass->lines = linesOf(mSlots, positions, axis, synthesis);
                const int n = axis < mGrid.dim ? mGrid.resolution[axis] : 1;
                const bool sine = axis == normal;
                fftw_r2r_kind fftKind = FFTW_REDFT01;
                if (axis >= mGrid.dim) {
                    pass->kind = AxisKind::Unused;
                } else if (mGrid.isPeriodic(axis)) {
                    pass->kind = AxisKind::PeriodicWave;
                    pass->length = n;
                    fftKind = synthesis ? FFTW_HC2R : FFTW_R2HC;
                    // z = e^{i(θ_l o + (phase − sine)π/2)}, o = ½ at a cell centre: the factor
                    // at x is Re(z e^{iθ_l x}); separableFactor reduces the angles exactly.
                    const int twiceX = sine ? 0 : 1;
                    for (int k = 0; k < pass->slots; ++k) {
                        const int l = k / 2, phase = k % 2;
                        const double re = separableFactor(mGrid, axis, l, phase, twiceX, sine);
                        // sin α = cos(α − π/2): one more quarter turn back.
                        const double im =
                            sine ? -separableFactor(mGrid, axis, l, phase, twiceX, false)
                                 : separableFactor(mGrid, axis, l, phase, twiceX, true);
                        pass->twiddle.emplace_back(re, im);
                    }
                } else if (sine) {
                    pass->kind = AxisKind::WallSine;
                    pass->length = n - 1;
                    fftKind = FFTW_RODFT00;
                } else {
                    pass->kind = AxisKind::WallCosine;
                    pass->length = n;
                    fftKind = synthesis ? FFTW_REDFT01 : FFTW_REDFT10;
                }
                if (pass->kind != AxisKind::Unused && pass->lines > 0) {
                    const std::size_t values = std::size_t(pass->lines) * std::size_t(pass->length);
                    pass->in = fftw_alloc_real(values);
                    pass->out = fftw_alloc_real(values);
                    if (!pass->in || !pass->out)
                        throw Error("separable transform: out of memory for its FFT buffers");
                    const int length = pass->length;
                    pass->plan = fftw_plan_many_r2r(1, &length, int(pass->lines), pass->in, nullptr,
                                                    1, length, pass->out, nullptr, 1, length,
                                                    &fftKind, FFTW_ESTIMATE);
                    if (!pass->plan) throw Error("separable transform: FFTW made no plan");
                }
                (synthesis ? mSynthesis : mAnalysis)[std::size_t(normal)][std::size_t(axis)] =
                    std::move(pass);
            }
    }
}

SeparableTransform::~SeparableTransform() = default;

int SeparableTransform::positionCount(int normal, int axis) const {
    if (axis >= mGrid.dim) return 1;
    const int n = mGrid.resolution[axis];
    return axis == normal && !mGrid.isPeriodic(axis) ? n - 1 : n;
}

int SeparableTransform::slotOf(const SeparableMode& mode, int axis) const {
    if (axis >= mGrid.dim) return 0;
    const int l = mode.wave[std::size_t(axis)];
    return mGrid.isPeriodic(axis) ? 2 * l + mode.shift[std::size_t(axis)] : l;
}

std::vector<double> SeparableTransform::factorTable(int normal, int axis) const {
    const int positions = positionCount(normal, axis), slots = mSlots[std::size_t(axis)];
    std::vector<double> table(std::size_t(positions) * std::size_t(slots), 1.0);
    if (axis >= mGrid.dim) return table;
    const bool sine = axis == normal, periodic = mGrid.isPeriodic(axis);
    for (int p = 0; p < positions; ++p) {
        // Faces at whole positions (a wall's first is its position 1), cells at half ones.
        const int twiceX = sine ? 2 * (p + (periodic ? 0 : 1)) : 2 * p + 1;
        for (int k = 0; k < slots; ++k)
            table[std::size_t(p) * std::size_t(slots) + std::size_t(k)] = separableFactor(
                mGrid, axis, periodic ? k / 2 : k, periodic ? k % 2 : 0, twiceX, sine);
    }
    return table;
}

std::size_t SeparableTransform::tensorSlot(const SeparableMode& mode) const {
    return (std::size_t(slotOf(mode, 2)) * std::size_t(mSlots[1]) + std::size_t(slotOf(mode, 1))) *
               std::size_t(mSlots[0]) +
           std::size_t(slotOf(mode, 0));
}

void SeparableTransform::synthesize(int normal, std::vector<double>& tensor) const {
    std::array<std::int64_t, 3> dims{mSlots[0], mSlots[1], mSlots[2]};
    std::vector<double> next;
    for (int axis = 0; axis < 3; ++axis) {
        mSynthesis[std::size_t(normal)][std::size_t(axis)]->run(tensor, dims[1], dims[2], next);
        dims = {dims[1], dims[2], positionCount(normal, axis)};
        tensor.swap(next);
    }
}

void SeparableTransform::analyze(int normal, std::vector<double>& tensor) const {
    std::array<std::int64_t, 3> dims{positionCount(normal, 0), positionCount(normal, 1),
                                     positionCount(normal, 2)};
    std::vector<double> next;
    for (int axis = 0; axis < 3; ++axis) {
        mAnalysis[std::size_t(normal)][std::size_t(axis)]->run(tensor, dims[1], dims[2], next);
        dims = {dims[1], dims[2], mSlots[std::size_t(axis)]};
        tensor.swap(next);
    }
}

Eigen::VectorXd SeparableTransform::fluxes(const Eigen::VectorXd& v) const {
    if (v.size() != Eigen::Index(mModes.size()))
        throw Error("separable transform: " + std::to_string(v.size()) +
                    " coefficients for a basis of " + std::to_string(mModes.size()) + " modes");
    Eigen::VectorXd out(mDofCount);
    const std::size_t slots =
        std::size_t(mSlots[0]) * std::size_t(mSlots[1]) * std::size_t(mSlots[2]);
    for (int normal = 0; normal < mGrid.dim; ++normal) {
        std::vector<double> tensor(slots, 0.0);
        for (std::size_t m = 0; m < mModes.size(); ++m) {
            const double amplitude = mModes[m].amplitude[std::size_t(normal)];
            if (amplitude == 0.0) continue;
            tensor[tensorSlot(mModes[m])] += v[Eigen::Index(m)] * amplitude;
        }
        synthesize(normal, tensor);
        const double area = mArea[std::size_t(normal)];
        const std::int64_t start = mDofStart[std::size_t(normal)];
        for (std::size_t d = 0; d < tensor.size(); ++d)
            out[Eigen::Index(start + std::int64_t(d))] = area * tensor[d];
    }
    return out;
}

Eigen::VectorXd SeparableTransform::transposed(const Eigen::VectorXd& q) const {
    if (q.size() != mDofCount)
        throw Error("separable transform: " + std::to_string(q.size()) +
                    " face values for a basis on " + std::to_string(mDofCount) + " faces");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(mModes.size()));
    for (int normal = 0; normal < mGrid.dim; ++normal) {
        std::int64_t count = 1;
        for (int a = 0; a < 3; ++a) count *= positionCount(normal, a);
        const std::int64_t start = mDofStart[std::size_t(normal)];
        std::vector<double> tensor(q.data() + start, q.data() + start + count);
        analyze(normal, tensor);
        const double area = mArea[std::size_t(normal)];
        for (std::size_t m = 0; m < mModes.size(); ++m) {
            const double amplitude = mModes[m].amplitude[std::size_t(normal)];
            if (amplitude == 0.0) continue;
            f[Eigen::Index(m)] += amplitude * area * tensor[tensorSlot(mModes[m])];
        }
    }
    return f;
}

}  // namespace modeflow
