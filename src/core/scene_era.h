/// \file
/// The two eras of the CS488 scene framework, and how a scene's calls tell them apart.
///
/// Before 2015 the framework post-multiplied transforms, so its scenes list them in reverse;
/// the current one applies them in the order written. A scene says nothing about its era, but
/// what it uses does: Lua-table meshes, `unpack`, `string.gfind` and seed 001's calls belong to
/// the old framework; meshes read from .obj files and seeds 000's and 002's calls to the new.
#pragma once

#include <string>
#include <vector>

namespace rb {

/// Which framework a scene was written for.
enum class Era { Modern, Legacy };

/// How the era is chosen: from the scene's signs, or forced by --modern or --legacy.
enum class EraChoice { Detect, Modern, Legacy };

/// One thing a scene used that belongs to one era, and where it first did.
struct EraSign {
    Era era;
    std::string what;   ///< e.g. "gr.mesh with Lua tables".
    std::string where;  ///< "scene.lua:12".
};

/// The era a scene is rendered in, and the one line that says why ("" when nothing to say).
struct EraDecision {
    Era era = Era::Modern;
    std::string line;
};

/// Decide the era: forced, else the only era with signs, else modern (saying so when the signs
/// conflict, or when there are none and `orderMatters` names the first transform whose order
/// changes the picture).
EraDecision decideEra(EraChoice choice, const std::vector<EraSign>& signs,
                      const std::string& orderMatters);

}  // namespace rb
