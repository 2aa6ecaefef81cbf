#include "core/scene_era.h"

#include <algorithm>

namespace rb {

namespace {

/// "gr.mesh with Lua tables (scene.lua:4), unpack (scene.lua:9)": the signs of one era.
std::string listSigns(const std::vector<EraSign>& signs, Era era) {
    std::string text;
    for (const EraSign& s : signs)
        if (s.era == era) text += (text.empty() ? "" : ", ") + s.what + " (" + s.where + ")";
    return text;
}

constexpr const char* kLegacyName = "pre-2015 framework (transforms listed in reverse)";
constexpr const char* kModernName = "current framework (transforms in the order written)";

}  // namespace

EraDecision decideEra(EraChoice choice, const std::vector<EraSign>& signs,
                      const std::string& orderMatters) {
    EraDecision d;
    if (choice != EraChoice::Detect) {
        d.era = choice == EraChoice::Legacy ? Era::Legacy : Era::Modern;
        d.line = std::string(d.era == Era::Legacy ? kLegacyName : kModernName) + ", forced by " +
                 (d.era == Era::Legacy ? "--legacy" : "--modern");
        return d;
    }
    const std::string legacy = listSigns(signs, Era::Legacy);
    const std::string modern = listSigns(signs, Era::Modern);
    // One era's signs alone decide it.
    if (!legacy.empty() && modern.empty()) {
        d.era = Era::Legacy;
        d.line = std::string(kLegacyName) + ", from " + legacy + "; --modern forces the other";
    } else if (legacy.empty() && !modern.empty()) {
        d.line = std::string(kModernName) + ", from " + modern + "; --legacy forces the other";
    } else if (!legacy.empty()) {
        d.line = std::string(kModernName) + " by default: the signs conflict (pre-2015: " + legacy +
                 "; current: " + modern + "); --legacy forces the other";
    } else if (!orderMatters.empty()) {
        // No signs: say so only when the choice changes the picture.
        d.line = std::string(kModernName) + " by default: no sign of either era, and the " +
                 "transforms' order matters (" + orderMatters + "); --legacy if written before 2015";
    }
    return d;
}

}  // namespace rb
