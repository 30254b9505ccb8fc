/// @file BasisSection.cpp
/// `[basis]`: which velocity modes (a count or a mode list), scalar modes, how the boundary is
/// treated and how the structural coefficients are kept.

#include "engine/core/PrintableText.h"
#include "precompute/scene/ModeList.h"
#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

BasisSpec readBasis(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kBasisKeys);
    BasisSpec basis;
    const toml::node* countNode = s.table.get("velocity_modes");
    const toml::node* listNode = s.table.get("modes");
    if (countNode != nullptr && listNode != nullptr) {
        reader.fail(s, "modes", "give either velocity_modes or modes, not both", listNode);
    }
    if (countNode == nullptr && listNode == nullptr) {
        reader.fail(s.name, "missing velocity_modes (a count, e.g. 40) or modes (e.g. \"1-115\")",
                    &s.table);
    }
    if (countNode != nullptr) {
        const int n = reader.readInt(s, "velocity_modes", 1, 1);
        basis.velocityModes = {ModeRange{1, n}};
    } else {
        const std::string text = *reader.string(s, "modes");
        if (auto problem = parseModeList(text, basis.velocityModes)) {
            reader.fail(s, "modes", "bad mode list \"" + printableText(text) + "\": " + *problem,
                        listNode);
        }
    }
    basis.scalarModes = reader.readInt(s, "scalar_modes", 0, 0);
    basis.scalarBoundary = reader.readChoice(s, "scalar_boundary", ScalarBoundary::Neumann,
                                             Choices<ScalarBoundary>(kScalarBoundaries));
    basis.wall = reader.readChoice(s, "wall", WallKind::FreeSlip, Choices<WallKind>(kWalls));
    basis.boundary = reader.readChoice(s, "boundary", BoundaryTreatment::CutCell,
                                       Choices<BoundaryTreatment>(kBoundaries));
    basis.subsamples = reader.readInt(s, "subsamples", 4, 1, 16);
    basis.coefficients = reader.readChoice(s, "coefficients", CoefficientStorage::Auto,
                                           Choices<CoefficientStorage>(kCoefficientStorages));
    basis.eigensolver = reader.readChoice(s, "eigensolver", EigensolverChoice::Automatic,
                                          Choices<EigensolverChoice>(kEigensolvers));
    return basis;
}

}  // namespace modeflow::scene
