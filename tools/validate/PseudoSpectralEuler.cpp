/// @file PseudoSpectralEuler.cpp
/// See PseudoSpectralEuler.h.

#include "tools/validate/PseudoSpectralEuler.h"

#include <cmath>
#include <numbers>

#include <fftw3.h>

#include "engine/core/Error.h"

namespace modeflow::validate {

/// One forward and one inverse 2D real transform with their own buffers (FFTW plans are made once).
struct PseudoSpectralEuler::Spectra {
    double* real = nullptr;
    fftw_complex* spectrum = nullptr;
    fftw_plan forward = nullptr, inverse = nullptr;
    Spectra(int n) {
        real = fftw_alloc_real(std::size_t(n) * n);
        spectrum = fftw_alloc_complex(std::size_t(n) * (n / 2 + 1));
        forward = fftw_plan_dft_r2c_2d(n, n, real, spectrum, FFTW_ESTIMATE);
        inverse = fftw_plan_dft_c2r_2d(n, n, spectrum, real, FFTW_ESTIMATE);
    }
    ~Spectra() {
        fftw_destroy_plan(forward);
        fftw_destroy_plan(inverse);
        fftw_free(real);
        fftw_free(spectrum);
    }
};

PseudoSpectralEuler::PseudoSpectralEuler(int n, double length) : mN(n), mLength(length) {
    if (n < 8 || n % 2 != 0 || !(length > 0.0))
        throw Error(
            "pseudo-spectral reference: the grid needs an even n ≥ 8 and a positive length");
    mSpectra = std::make_unique<Spectra>(n);
    mOmega.assign(std::size_t(n) * (n / 2 + 1), 0.0);
}

PseudoSpectralEuler::~PseudoSpectralEuler() = default;

double PseudoSpectralEuler::waveNumber(int axis, int index) const {
    // Rows (axis 1) run over all n wave numbers, columns (axis 0) over 0 … n/2.
    const int signedIndex = axis == 1 && index > mN / 2 ? index - mN : index;
    return 2.0 * std::numbers::pi / mLength * signedIndex;
}

bool PseudoSpectralEuler::kept(int row, int column) const {
    const int ky = row > mN / 2 ? mN - row : row;
    return 3 * ky < mN && 3 * column < mN;
}

std::vector<double> PseudoSpectralEuler::synthesize(const Spectrum& c, double shiftX,
                                                    double shiftY) const {
    const int columns = mN / 2 + 1;
    for (int row = 0; row < mN; ++row)
        for (int column = 0; column < columns; ++column) {
            const double phase = waveNumber(0, column) * shiftX + waveNumber(1, row) * shiftY;
            const std::complex<double> value =
                c[std::size_t(row) * columns + column] * std::polar(1.0, phase);
            mSpectra->spectrum[std::size_t(row) * columns + column][0] = value.real();
            mSpectra->spectrum[std::size_t(row) * columns + column][1] = value.imag();
        }
    fftw_execute(mSpectra->inverse);
    return {mSpectra->real, mSpectra->real + std::size_t(mN) * mN};
}

PseudoSpectralEuler::Spectrum PseudoSpectralEuler::analyze(std::span<const double> samples,
                                                           double shiftX, double shiftY) const {
    std::copy(samples.begin(), samples.end(), mSpectra->real);
    fftw_execute(mSpectra->forward);
    const int columns = mN / 2 + 1;
    const double scale = 1.0 / (double(mN) * mN);
    Spectrum c(std::size_t(mN) * columns);
    for (int row = 0; row < mN; ++row)
        for (int column = 0; column < columns; ++column) {
            const double* s = mSpectra->spectrum[std::size_t(row) * columns + column];
            const double phase = waveNumber(0, column) * shiftX + waveNumber(1, row) * shiftY;
            c[std::size_t(row) * columns + column] =
                std::complex<double>(s[0], s[1]) * scale * std::polar(1.0, -phase);
        }
    return c;
}

void PseudoSpectralEuler::setFaceVelocity(std::span<const double> faces) {
    const std::size_t cells = std::size_t(mN) * mN;
    if (faces.size() != 2 * cells)
        throw Error("pseudo-spectral reference: a face field of " + std::to_string(faces.size()) +
                    " values for a grid of " + std::to_string(2 * cells) + " faces");
    const double h = mLength / mN;
    const Spectrum ux = analyze(faces.subspan(0, cells), 0.0, 0.5 * h);
    const Spectrum uy = analyze(faces.subspan(cells), 0.5 * h, 0.0);
    const int columns = mN / 2 + 1;
    const std::complex<double> i(0.0, 1.0);
    for (int row = 0; row < mN; ++row)
        for (int column = 0; column < columns; ++column) {
            const std::size_t k = std::size_t(row) * columns + column;
            mOmega[k] = kept(row, column)
                            ? i * (waveNumber(0, column) * uy[k] - waveNumber(1, row) * ux[k])
                            : 0.0;
        }
    mMean[0] = ux[0].real(), mMean[1] = uy[0].real();
}

std::vector<double> PseudoSpectralEuler::faceVelocity() const {
    const int columns = mN / 2 + 1;
    const std::complex<double> i(0.0, 1.0);
    Spectrum ux(mOmega.size()), uy(mOmega.size());
    for (int row = 0; row < mN; ++row)
        for (int column = 0; column < columns; ++column) {
            const std::size_t k = std::size_t(row) * columns + column;
            const double kx = waveNumber(0, column), ky = waveNumber(1, row),
                         k2 = kx * kx + ky * ky;
            if (k2 == 0.0) continue;
            // u = ∂ψ/∂y, v = −∂ψ/∂x, ψ̂ = ω̂ / |k|².
            ux[k] = i * ky * mOmega[k] / k2, uy[k] = -i * kx * mOmega[k] / k2;
        }
    ux[0] = mMean[0], uy[0] = mMean[1];
    const double h = mLength / mN;
    std::vector<double> faces = synthesize(ux, 0.0, 0.5 * h);
    const std::vector<double> y = synthesize(uy, 0.5 * h, 0.0);
    faces.insert(faces.end(), y.begin(), y.end());
    return faces;
}

PseudoSpectralEuler::Spectrum PseudoSpectralEuler::rate(const Spectrum& w) const {
    const int columns = mN / 2 + 1;
    const std::complex<double> i(0.0, 1.0);
    Spectrum ux(w.size()), uy(w.size()), wx(w.size()), wy(w.size());
    for (int row = 0; row < mN; ++row)
        for (int column = 0; column < columns; ++column) {
            const std::size_t k = std::size_t(row) * columns + column;
            const double kx = waveNumber(0, column), ky = waveNumber(1, row),
                         k2 = kx * kx + ky * ky;
            if (k2 == 0.0) continue;
            ux[k] = i * ky * w[k] / k2, uy[k] = -i * kx * w[k] / k2;
            wx[k] = i * kx * w[k], wy[k] = i * ky * w[k];
        }
    ux[0] = mMean[0], uy[0] = mMean[1];
    const std::vector<double> u = synthesize(ux, 0.0, 0.0), v = synthesize(uy, 0.0, 0.0),
                              dx = synthesize(wx, 0.0, 0.0), dy = synthesize(wy, 0.0, 0.0);
    std::vector<double> advection(u.size());
    for (std::size_t p = 0; p < u.size(); ++p) advection[p] = -(u[p] * dx[p] + v[p] * dy[p]);
    Spectrum out = analyze(advection, 0.0, 0.0);
    for (int row = 0; row < mN; ++row)
        for (int column = 0; column < columns; ++column)
            if (!kept(row, column)) out[std::size_t(row) * columns + column] = 0.0;
    return out;
}

void PseudoSpectralEuler::step(double h) {
    const auto plus = [](const Spectrum& a, const Spectrum& b, double s) {
        Spectrum c(a.size());
        for (std::size_t k = 0; k < a.size(); ++k) c[k] = a[k] + s * b[k];
        return c;
    };
    const Spectrum k1 = rate(mOmega), k2 = rate(plus(mOmega, k1, 0.5 * h)),
                   k3 = rate(plus(mOmega, k2, 0.5 * h)), k4 = rate(plus(mOmega, k3, h));
    for (std::size_t k = 0; k < mOmega.size(); ++k)
        mOmega[k] += h / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
}

double PseudoSpectralEuler::energy() const {
    const int columns = mN / 2 + 1;
    double sum = 0.0;
    for (int row = 0; row < mN; ++row)
        for (int column = 0; column < columns; ++column) {
            const double kx = waveNumber(0, column), ky = waveNumber(1, row),
                         k2 = kx * kx + ky * ky;
            if (k2 == 0.0) continue;
            // Columns 1 … n/2 − 1 stand for their conjugates too.
            const double weight = column == 0 || 2 * column == mN ? 1.0 : 2.0;
            sum += weight * std::norm(mOmega[std::size_t(row) * columns + column]) / k2;
        }
    return 0.5 * mLength * mLength * (sum + mMean[0] * mMean[0] + mMean[1] * mMean[1]);
}

}  // namespace modeflow::validate
