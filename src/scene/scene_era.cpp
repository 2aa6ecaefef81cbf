#include "scene/scene_era.h"

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

/// ", and 2 more nodes" after an idiom's first place, when it was seen on more than one node.
std::string moreNodes(int votes) {
    return votes > 2   ? ", and " + std::to_string(votes - 1) + " more nodes"
           : votes > 1 ? ", and 1 more node"
                       : "";
}

constexpr const char* kLegacyName = "pre-2015 framework (transforms listed in reverse)";
constexpr const char* kModernName = "current framework (transforms in the order written)";

}  // namespace

EraDecision decideEra(EraChoice choice, const std::vector<EraSign>& signs,
                      const std::string& orderMatters, const EraIdiom& idiom) {
    EraDecision d;
    if (choice != EraChoice::Detect) {
        d.era = choice == EraChoice::Legacy ? Era::Legacy : Era::Modern;
        d.line = std::string(d.era == Era::Legacy ? kLegacyName : kModernName) + ", forced by " +
                 (d.era == Era::Legacy ? "--legacy" : "--modern");
        d.show = d.era == Era::Legacy;
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
        d.show = !orderMatters.empty();
    } else if (idiom.legacyVotes > 0 && idiom.modernVotes == 0) {
        // No sign: the way scaled objects are placed tells, when only one era's way is seen.
        d.era = Era::Legacy;
        d.line = std::string(kLegacyName) +
                 ", from its transforms: scaled objects placed the pre-2015 way (translate or " +
                 "rotate, then scale) at " + idiom.firstLegacy + moreNodes(idiom.legacyVotes) +
                 "; --modern forces the other";
    } else if (idiom.modernVotes > 0 && idiom.legacyVotes == 0) {
        d.line = std::string(kModernName) +
                 ", from its transforms: scaled objects placed the current way (scale, then " +
                 "rotate or translate) at " + idiom.firstModern + moreNodes(idiom.modernVotes) +
                 "; --legacy forces the other";
    } else if (!orderMatters.empty()) {
        // No sign and no clear idiom: a guess, said because the choice changes the picture.
        d.line = std::string(kModernName) + " by default: no sign of either era" +
                 (idiom.legacyVotes > 0
                      ? " and scaled objects placed both ways (pre-2015: " + idiom.firstLegacy +
                            "; current: " + idiom.firstModern + ")"
                      : "") +
                 ", and the transforms' order matters (" + orderMatters +
                 "); --legacy if written before 2015";
        d.show = true;
    } else {
        d.line = std::string(kModernName) +
                 " by default: no sign of either era, and the transforms' order does not matter";
    }
    d.show = d.show || d.era == Era::Legacy;
    return d;
}

}  // namespace rb
