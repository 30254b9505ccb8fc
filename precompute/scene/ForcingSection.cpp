/// @file ForcingSection.cpp
/// `[forcing]`: the velocity modes held at their initial amplitudes, by position in the basis
/// (`hold_modes = "1-5"`) or by wave number (`hold_below_kappa = 2.0`), one of the two.

#include "engine/core/PrintableText.h"
#include "precompute/scene/ModeList.h"
#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

ForcingSpec readForcing(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kForcingKeys);
    ForcingSpec forcing;
    const toml::node* modes = s.table.get("hold_modes");
    const toml::node* kappa = s.table.get("hold_below_kappa");
    if (modes != nullptr && kappa != nullptr)
        reader.fail(s, "hold_below_kappa", "give either hold_modes or hold_below_kappa, not both",
                    kappa);
    if (modes == nullptr && kappa == nullptr)
        reader.fail(s.name, "missing hold_modes (e.g. \"1-5\") or hold_below_kappa (e.g. 2.0)",
                    &s.table);
    if (modes != nullptr) {
        const std::string text = *reader.string(s, "hold_modes");
        if (auto problem = parseModeList(text, forcing.holdModes))
            reader.fail(s, "hold_modes",
                        "bad mode list \"" + printableText(text) + "\": " + *problem, modes);
    } else {
        forcing.holdBelowKappa = reader.readNumber(s, "hold_below_kappa", 0.0, Sign::Positive);
    }
    return forcing;
}

}  // namespace modeflow::scene
