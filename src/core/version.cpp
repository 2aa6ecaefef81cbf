#include "core/version.h"

namespace rb {

std::string versionText(const std::vector<Feature>& built) {
    std::string names;
    for (const Feature& f : built) names += std::string(names.empty() ? "" : ", ") + f.name;
    const int last = built.empty() ? 0 : built.back().chapter;
    const std::string chapters = last == 1 ? "chapter 1" : "chapters 1-" + std::to_string(last);
    return std::string("raybook ") + versionNumber() + " (commit " + gitCommit() + ")\n" +
           chapters + ": " + names + "\n";
}

}  // namespace rb
