#pragma once
/// @file LinearModalTerm.h
/// A constant linear term D v added to the reduced model's right-hand side (FluidSystem): the
/// advection of the modes by a held base flow, a wind (engine/simulation/WindTransport.h). D need
/// not be antisymmetric: vᵀ D v is the power the term puts in or takes out (for a wind, the
/// kinetic energy it carries out through the downstream sides).

#include <Eigen/Core>

namespace modeflow {

class LinearModalTerm {
public:
    virtual ~LinearModalTerm() = default;

    /// N, the number of modes D acts on.
    virtual int size() const = 0;
    /// out = D v.
    virtual void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const = 0;
    /// D as a dense N × N matrix, for solvers that form Jacobians (formed on the first call).
    virtual const Eigen::MatrixXd& matrix() const = 0;
};

}  // namespace modeflow
