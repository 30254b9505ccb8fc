#include "precompute/solve/EigenMethod.h"

namespace modeflow {

EigenMethod chooseEigenMethod(std::int64_t unknowns, std::int64_t count, EigensolverChoice choice,
                              int ranks) {
    if (unknowns <= kDenseLimit) return EigenMethod::Dense;
    switch (choice) {
        case EigensolverChoice::Spectra:
            return EigenMethod::Lanczos;
        case EigensolverChoice::Block:
            return EigenMethod::BlockLanczos;
        case EigensolverChoice::Slepc:
            return EigenMethod::Slicing;
        case EigensolverChoice::Automatic:
            break;
    }
    if (count >= kSlicingFromCount || ranks > 1) return EigenMethod::Slicing;
    return count >= kBlockLanczosFromCount ? EigenMethod::BlockLanczos : EigenMethod::Lanczos;
}

}  // namespace modeflow
