#include "app/version.h"

namespace rb {

std::string versionText(const std::vector<Feature>& built) {
    std::string names;
    for (const Feature& f : built) names += std::string(names.empty() ? "" : ", ") + f.name;
    // Runs of consecutive chapters: "1-8, 10" when chapter 9 is not written yet.
    std::string runs;
    int count = 0;
    for (std::size_t i = 0; i < built.size(); ++i) {
        const int first = built[i].chapter;
        while (i + 1 < built.size() && built[i + 1].chapter == built[i].chapter + 1) ++i;
        const int last = built[i].chapter;
        runs += (runs.empty() ? "" : ", ") + std::to_string(first) +
                (last > first ? "-" + std::to_string(last) : "");
        count += last - first + 1;
    }
    const std::string chapters = (count == 1 ? "chapter " : "chapters ") + runs;
    return std::string("raybook ") + versionNumber() + " (commit " + gitCommit() + ")\n" +
           chapters + ": " + names + "\n";
}

}  // namespace rb
