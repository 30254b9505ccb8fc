#include "tools/validate/Studies.h"

namespace modeflow::validate {

const std::vector<Study>& allStudies() {
    static const std::vector<Study> studies = {
        {"convergence", "eigenvalue error against the disk's and ball's closed forms, by resolution",
         convergenceStudy},
        {"integrators", "energy over time for each integrator and step, and reversibility", integratorStudy},
    };
    return studies;
}

}  // namespace modeflow::validate
