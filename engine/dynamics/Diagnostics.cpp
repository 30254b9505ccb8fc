#include "engine/dynamics/Diagnostics.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

void requireSameSize(const char* what, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    if (a.size() != b.size()) {
        throw Error(std::string(what) + ": vectors of " + std::to_string(a.size()) + " and " +
                    std::to_string(b.size()) + " entries");
    }
}

}  // namespace

double energy(const Eigen::VectorXd& v) {
    return 0.5 * v.squaredNorm();
}

double lansEnergy(const Eigen::VectorXd& v, const Eigen::VectorXd& kappaSquared, double alpha) {
    requireSameSize("LANS-alpha energy", v, kappaSquared);
    return 0.5 * ((1.0 + alpha * alpha * kappaSquared.array()) * v.array().square()).sum();
}

double crossHelicity(const Eigen::VectorXd& v, const Eigen::VectorXd& f) {
    requireSameSize("cross helicity", v, f);
    return v.dot(f);
}

double enstrophy(const Eigen::VectorXd& v, const Eigen::VectorXd& kappaSquared) {
    requireSameSize("enstrophy", v, kappaSquared);
    return (kappaSquared.array() * v.array().square()).sum();
}

}  // namespace modeflow
