#include "core/version.h"

namespace rb {

std::string versionText(const std::vector<Feature>& built) {
    std::string names;
    for (const Feature& f : built) names += std::string(names.empty() ? "" : ", ") + f.name;
    const int last = built.empty() ? 0 : built.back().chapter;
    return std::string("raybook ") + versionNumber() + " (commit " + gitCommit() + ")\n" +
           "chapters 1-" + std::to_string(last) + ": " + names + "\n";
}

}  // namespace rb
