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

/// How the scene places scaled objects, when it has no sign: on one node, a translate written
/// before a scale it does not commute with is the pre-2015 idiom (post-multiplied, the scale
/// acts first); a scale written before a translate is the current one. One vote per node.
struct EraIdiom {
    int legacyVotes = 0, modernVotes = 0;
    std::string firstLegacy, firstModern;  ///< Where each idiom was first seen ("scene.lua:7").
};

/// The era a scene is rendered in, and the line that says why.
struct EraDecision {
    Era era = Era::Modern;
    std::string line;   ///< What was decided and why; never empty (--stats shows it).
    bool show = false;  ///< Worth a line on stderr: pre-2015, or a guess whose order matters.
};

/// Decide the era: forced, else the only era with signs, else, with no sign at all, the
/// transform idiom when only one era's is seen, else current. `show` is set when the scene
/// renders pre-2015, or when the order was guessed (conflicting signs, or none and no idiom)
/// and `orderMatters` names the first transform whose order changes the picture.
EraDecision decideEra(EraChoice choice, const std::vector<EraSign>& signs,
                      const std::string& orderMatters, const EraIdiom& idiom = {});

}  // namespace rb
