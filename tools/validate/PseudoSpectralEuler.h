#pragma once
/// @file PseudoSpectralEuler.h
/// The full-spectrum reference of `reduced_vs_full`'s periodic experiment: the 2D incompressible
/// Euler equations on a periodic n × n grid of the box [0, L)², solved pseudo-spectrally in
/// vorticity form (FFTW real transforms, ∂ω/∂t = −u·∇ω, u = ∇⊥ψ, −Δψ = ω), dealiased by the 2/3
/// rule and stepped with classical RK4. Every wave vector the dealiased grid holds is a degree of
/// freedom: the "full variational integrator with 256² degrees of freedom" of seed Fig. 6.12.
///
/// It trades with modeflow's runs through MAC face fields (engine/core/MacGrid.h on a periodic
/// grid: u_x at (i h, (j + ½) h), u_y at ((i + ½) h, j h), x fastest): the Fourier series is
/// sampled at, and read from, the staggered positions by half-cell phase shifts.

#include <complex>
#include <memory>
#include <span>
#include <vector>

namespace modeflow::validate {

class PseudoSpectralEuler {
public:
    /// An n × n grid (n even, at least 8) of the box [0, length)², at rest.
    PseudoSpectralEuler(int n, double length);
    ~PseudoSpectralEuler();
    PseudoSpectralEuler(const PseudoSpectralEuler&) = delete;
    PseudoSpectralEuler& operator=(const PseudoSpectralEuler&) = delete;

    /// The vorticity of the face field `faces` (2 n² values: all x faces, then all y faces),
    /// dealiased: its divergence-free, band-limited part becomes the state.
    void setFaceVelocity(std::span<const double> faces);
    /// The state's velocity sampled at the faces (2 n² values, as setFaceVelocity takes).
    std::vector<double> faceVelocity() const;
    /// One RK4 step of size h.
    void step(double h);
    /// ½ ∫ |u|² over the box.
    double energy() const;

private:
    struct Spectra;
    using Spectrum = std::vector<std::complex<double>>;
    /// dω̂/dt = −FFT(u·∇ω), dealiased, for the vorticity spectrum `w`.
    Spectrum rate(const Spectrum& w) const;
    /// Σ_k c_k e^{i k·(x_j + shift)} at the grid's points (c on the half spectrum).
    std::vector<double> synthesize(const Spectrum& c, double shiftX, double shiftY) const;
    /// The coefficients c_k of the samples f(x_j + shift), f band-limited below the Nyquist.
    Spectrum analyze(std::span<const double> samples, double shiftX, double shiftY) const;
    double waveNumber(int axis, int index) const;
    bool kept(int row, int column) const;  ///< inside the 2/3 rule

    int mN;
    double mLength;
    std::unique_ptr<Spectra> mSpectra;
    Spectrum mOmega;               ///< ω̂, n rows (k_y) × (n/2 + 1) columns (k_x), dealiased
    double mMean[2] = {0.0, 0.0};  ///< the mean flow (the torus's harmonic fields)
};

}  // namespace modeflow::validate
