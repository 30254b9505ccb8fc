#include "tools/validate/Studies.h"

namespace modeflow::validate {

const std::vector<Study>& allStudies() {
    static const std::vector<Study> studies = {
        {"convergence",
         "eigenvalue error against the disk's and ball's closed forms, by resolution",
         convergenceStudy},
        {"integrators", "energy over time for each integrator and step, and reversibility",
         integratorStudy},
        {"mhd",
         "the MHD rotor: energies and cross helicity over time, the dye with and without the field",
         mhdStudy},
        {"coefficients",
         "our antisymmetric coefficients against grid-evaluated advection, error against a full "
         "run",
         coefficientStudy},
        {"resolution", "one smoke scene on three grids: centroid path, modal energy, pictures",
         resolutionStudy},
        {"speed", "seconds per reduced-dynamics step against the seed's published figures",
         speedStudy},
        {"reduced_vs_full",
         "reduced runs of N modes against the full run of every mode of the grid",
         reducedVsFullStudy},
        {"lans_alpha",
         "forced 3D turbulence: spectra and energy flux, Navier–Stokes against LANS-α",
         lansAlphaStudy},
        {"wake",
         "vortex shedding behind a cylinder in a wind: the Strouhal number against Roshko's",
         wakeStudy},
    };
    return studies;
}

}  // namespace modeflow::validate
