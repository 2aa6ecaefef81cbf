#include "core/feature.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/image.h"
#include "written_chapters.h"  // generated into the build folder by CMakeLists.txt

namespace rb {

FeatureSet::FeatureSet(const std::vector<Feature>& built, const std::string& spec) : built_(built) {
    std::set<std::string> on;
    for (const Feature& f : built)
        if (!f.switchable) on.insert(f.name);
    // Read the comma-separated list left to right: "all", "name" or "-name". A list that
    // starts by switching something off starts from everything built: "-glossy" means
    // "all,-glossy", not "nothing but the core".
    std::stringstream list(spec.rfind('-', 0) == 0 ? "all," + spec : spec);
    std::string item;
    while (std::getline(list, item, ',')) {
        if (item.empty()) continue;
        const bool off = item[0] == '-';
        const std::string name = off ? item.substr(1) : item;
        if (name == "all") {
            for (const Feature& f : built)
                if (off && f.switchable)
                    on.erase(f.name);
                else if (!off)
                    on.insert(f.name);
            continue;
        }
        auto it = std::find_if(built.begin(), built.end(),
                               [&](const Feature& f) { return name == f.name; });
        if (it == built.end()) {
            std::string known;
            for (const Feature& f : built) known += std::string(known.empty() ? "" : ", ") + f.name;
            std::string title;
            const int chapter = chapterProviding(name, title);
            throw InputError("--features: '" + name + "' is not in this build" +
                             (chapter ? " (it is chapter " + std::to_string(chapter) + "; " +
                                            chapterAdvice(chapter) + ")"
                                      : "") +
                             "; built features: " + known);
        }
        if (off && !it->switchable)
            throw InputError("--features: '" + name + "' is part of the core (chapter " +
                             std::to_string(it->chapter) + ") and cannot be switched off");
        if (off)
            on.erase(name);
        else
            on.insert(name);
    }
    for (const Feature& f : built)
        if (on.count(f.name)) on_.push_back(f);
}

bool FeatureSet::enabled(const std::string& name) const {
    return std::any_of(on_.begin(), on_.end(), [&](const Feature& f) { return name == f.name; });
}

const OutputFormat* outputFormatFor(const std::vector<Feature>& features, const std::string& path) {
    const std::string ext = lowerExtension(path);
    for (const Feature& f : features)
        for (const OutputFormat& format : f.outputFormats)
            if (ext == format.extension) return &format;
    return nullptr;
}

namespace {
/// Lua calls and feature names of chapters that may be missing from a build.
struct LaterCall {
    const char* name;
    int chapter;
    const char* module;
};
constexpr LaterCall kLaterCalls[] = {
    {"mesh", 3, "meshes and the BVH"},
    {"obj_mesh", 3, "meshes and the BVH"},
    {"bvh", 3, "meshes and the BVH"},
    {"reflection", 4, "reflection"},
    {"phongMat", 4, "reflection"},
    {"fancy_material", 4, "reflection"},
    {"reflect", 4, "reflection"},
    {"ior", 5, "refraction"},
    {"transparency", 5, "refraction"},
    {"schlick", 5, "refraction"},
    {"glossiness", 7, "glossy"},
    {"glossy_sampler", 7, "glossy"},
    {"light_samples", 6, "soft_shadows"},
    {"glossy_samples", 7, "glossy"},
    {"refraction", 5, "refraction"},
    {"transMat", 5, "refraction"},
    {"soft_shadows", 6, "soft_shadows"},
    {"ball_light", 6, "soft_shadows"},
    {"area_light", 6, "soft_shadows"},
    {"glossy", 7, "glossy"},
    {"adaptive_aa", 8, "adaptive_aa"},
    {"antialias", 8, "adaptive_aa"},
    {"aa_sampler", 8, "adaptive_aa"},
    {"aa_samples", 8, "adaptive_aa"},
    {"aa_threshold", 8, "adaptive_aa"},
    {"aa_depth", 8, "adaptive_aa"},
    {"smooth_mesh", 9, "smooth_mesh"},
    {"terminator", 9, "smooth_mesh"},
    {"texture", 10, "texture"},
    {"bump", 11, "bump"},
    {"tone_map", 12, "tone_map"},
    {"tone_key", 12, "tone_map"},
    {"tone_white", 12, "tone_map"},
    {"tone_sharpness", 12, "tone_map"},
    {"tone_threshold", 12, "tone_map"},
    {"exposure", 12, "tone_map"},
    {"srgb", 12, "tone_map"},
    {"dof", 13, "dof"},
    {"lens", 13, "dof"},
    {"dof_aperture", 13, "dof"},
    {"dof_focus", 13, "dof"},
    {"dof_samples", 13, "dof"},
    {"dof_shape", 13, "dof"},
    {"csg", 14, "csg"},
    {"union", 14, "csg"},
    {"intersection", 14, "csg"},
    {"difference", 14, "csg"},
    {"set_texture_map", 10, "texture"},
    {"set_texture", 10, "texture"},
    {"set_bump_map", 11, "bump"},
    {"set_bump", 11, "bump"},
    {"quadrics", 15, "quadrics"},
    {"cone", 15, "quadrics"},
    {"cylinder", 15, "quadrics"},
    {"cyllinder", 15, "quadrics"},
    {"photon_map", 16, "photon_map"},
    {"photons", 16, "photon_map"},
    {"caustics", 16, "photon_map"},
    {"media", 17, "media"},
    {"medium", 17, "media"},
    {"fog", 17, "media"},
    {"set_medium", 17, "media"},
    {"path_tracing", 18, "path_tracing"},
    {"integrator", 18, "path_tracing"},
    {"emission", 18, "path_tracing"},
    {"integrator_path", 18, "path_tracing"},
    {"path_depth", 18, "path_tracing"},
    {"path_roulette", 18, "path_tracing"},
};
}  // namespace

#if !defined(RB_NEWEST_CHAPTER) || !defined(RB_WRITTEN_CHAPTERS)
#error "written_chapters.h (generated by CMakeLists.txt) defines RB_NEWEST_CHAPTER and RB_WRITTEN_CHAPTERS"
#endif
int newestChapter() {
    return RB_NEWEST_CHAPTER;
}

bool chapterWritten(int chapter) {
    for (int written : {RB_WRITTEN_CHAPTERS})
        if (written == chapter) return true;
    return false;
}

std::string chapterAdvice(int chapter) {
    const std::string n = std::to_string(chapter);
    if (!chapterWritten(chapter)) return "chapter " + n + " is planned but not written yet";
    return "build it with make chapter" + n + " or later";
}

int chapterProviding(const std::string& name, std::string& title) {
    for (const LaterCall& c : kLaterCalls)
        if (name == c.name) {
            title = c.module;
            return c.chapter;
        }
    return 0;
}

}  // namespace rb
