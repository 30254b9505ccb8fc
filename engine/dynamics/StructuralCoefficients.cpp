#include "engine/dynamics/StructuralCoefficients.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {

void StructuralCoefficients::jacobian(const Eigen::VectorXd& v, Eigen::MatrixXd& jac,
                                      Eigen::VectorXd& f) const {
    Eigen::MatrixXd byJ;
    linearize(v, v, jac, byJ);
    f.noalias() = jac * v;
    jac += byJ;
}

void StructuralCoefficients::checkSize(const char* operation, const Eigen::VectorXd& a) const {
    if (a.size() != size()) {
        throw Error(std::string("structural coefficients: ") + operation + " got a vector of " +
                    std::to_string(a.size()) + " entries for " + std::to_string(size()) + " modes");
    }
}

}  // namespace modeflow
