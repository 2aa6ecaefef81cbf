#include "app/render_warnings.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "core/image.h"

namespace rb {

namespace {

/// A gr.render argument of seed 001 and the chapter that gives it meaning.
struct DialectArgument {
    const char* key;      ///< Its name in RenderJob::options.
    const char* label;    ///< How the message names it.
    const char* feature;  ///< The feature that reads it.
    int chapter;
};
constexpr DialectArgument kDialectArguments[] = {
    {"aa", "aa argument (antialiasing)", "adaptive_aa", 8},
    {"ss", "ss argument (soft-shadow samples)", "soft_shadows", 6},
    {"dist", "dist argument (glossy samples)", "glossy", 7},
    // Seed 001 switches depth of field on with dof > 0; the aperture alone does nothing.
    {"dof", "dof argument (depth of field)", "dof", 13},
};

/// Why `feature` (of `chapter`) does nothing in this run.
std::string whyAbsent(const FeatureSet& features, const char* feature, int chapter) {
    const bool built =
        std::any_of(features.built().begin(), features.built().end(),
                    [&](const Feature& f) { return std::string(feature) == f.name; });
    if (built) return "--features switched it off";
    return "this build does not have it; " + chapterAdvice(chapter);
}

/// Whether `node` leaves anything solid to draw: a shape, a group with such a child, or a
/// compound (CSG) node whose own rule keeps some of its children; each compound node that
/// keeps nothing adds a warning. Memoised, since the graph may share subgraphs.
bool leavesShapes(const SceneNode& node, const FeatureSet& features, const std::string& where,
                  std::map<const SceneNode*, bool>& done, std::vector<std::string>& warnings) {
    if (auto it = done.find(&node); it != done.end()) return it->second;
    done[&node] = false;  // the graph is acyclic; this only guards the recursion
    std::vector<bool> childHasShapes;
    for (const auto& child : node.children)
        childHasShapes.push_back(leavesShapes(*child, features, where, done, warnings));
    bool result = node.shape != nullptr;
    if (node.compound && features.enabled(node.compound->feature())) {
        const std::string why = node.compound->whyEmpty(childHasShapes);
        if (!why.empty())
            warnings.push_back(where + ": the CSG node '" + node.name + "' is empty, so it " +
                               "draws nothing: " + why + " (did you add_child to its operands?)");
        result = result || why.empty();
    } else {
        result = result || std::find(childHasShapes.begin(), childHasShapes.end(), true) !=
                               childHasShapes.end();
    }
    return done[&node] = result;
}

}  // namespace

std::vector<std::string> renderWarnings(const RenderJob& job,
                                        const std::vector<Instance>& instances,
                                        const PinholeCamera& camera, const FeatureSet& features,
                                        const std::string& output) {
    std::vector<std::string> warnings;
    // Nothing to see: no shapes at all, or none inside the view.
    if (instances.empty())
        warnings.push_back(job.where + ": the root node has no shapes under it, so the image " +
                           "will be empty (did you add_child?)");
    else if (std::none_of(instances.begin(), instances.end(),
                          [&](const Instance& i) { return camera.mayShow(i.worldBounds); }))
        warnings.push_back(job.where + ": no shape is in front of the camera, so the image " +
                           "will show only the background (check eye, view, up and fovy)");
    // Seed 001's arguments that only a chapter not in use would read.
    for (const DialectArgument& a : kDialectArguments) {
        const auto it = job.options.find(a.key);
        if (it == job.options.end() || it->second == 0.0 || features.enabled(a.feature)) continue;
        warnings.push_back(job.where + ": gr.render's " + a.label +
                           " is ignored: it needs chapter " + std::to_string(a.chapter) + " (" +
                           a.feature + "), and " + whyAbsent(features, a.feature, a.chapter));
    }
    // Chapter 8's own options, when the chapter is built but switched off.
    const auto sampler = job.options.find("aa_sampler");
    if (sampler != job.options.end() && sampler->second != 0.0 && !features.enabled("adaptive_aa"))
        warnings.push_back(job.where + ": the scene's antialiasing (gr.antialias or aa_sampler) " +
                           "is ignored: it needs chapter 8 (adaptive_aa), and " +
                           whyAbsent(features, "adaptive_aa", 8));
    // Chapter 10's textures, when the chapter is built but switched off (only a build with it
    // can have put a texture on a material).
    if (!features.enabled("texture") &&
        std::any_of(instances.begin(), instances.end(),
                    [](const Instance& i) { return i.material && !i.material->textures.empty(); }))
        warnings.push_back(job.where + ": the scene's textures (gr.texture, set_texture or " +
                           "set_texture_map) are ignored: they need chapter 10 (texture), and " +
                           whyAbsent(features, "texture", 10));
    // Chapter 11's bumps, when the chapter is built but switched off (only a build with it can
    // have put a bump on a material).
    if (!features.enabled("bump") &&
        std::any_of(instances.begin(), instances.end(),
                    [](const Instance& i) { return i.material && i.material->bump; }))
        warnings.push_back(job.where + ": the scene's bumps (set_bump or set_bump_map) are " +
                           "ignored: they need chapter 11 (bump), and " +
                           whyAbsent(features, "bump", 11));
    // Chapter 12's display settings, when the chapter is built but switched off.
    bool toneMapAsked = false;
    for (const char* name : {"tone_map", "exposure", "srgb"}) {
        const auto it = job.options.find(name);
        if (it != job.options.end() && it->second != 0.0) toneMapAsked = true;
    }
    if (toneMapAsked && !features.enabled("tone_map"))
        warnings.push_back(job.where + ": the scene's tone map (gr.tone_map, tone_map, exposure " +
                           "or srgb) is ignored: it needs chapter 12 (tone_map), and " +
                           whyAbsent(features, "tone_map", 12));
    // Chapter 13's own lens, when the chapter is built but switched off.
    const auto aperture = job.options.find("dof_aperture");
    if (aperture != job.options.end() && aperture->second != 0.0 && !features.enabled("dof"))
        warnings.push_back(job.where + ": the scene's lens (gr.lens or dof_aperture) is " +
                           "ignored: it needs chapter 13 (dof), and " +
                           whyAbsent(features, "dof", 13));
    // Chapter 16's photons, when the chapter is built but switched off.
    const auto photons = job.options.find("photons");
    if (photons != job.options.end() && photons->second != 0.0 && !features.enabled("photon_map"))
        warnings.push_back(job.where + ": the scene's photons (gr.photons) are ignored: they " +
                           "need chapter 16 (photon_map), and " +
                           whyAbsent(features, "photon_map", 16));
    // Compound nodes (chapter 14's CSG) whose feature is off are drawn as plain groups.
    if (job.root) {
        std::vector<const SceneNode*> stack = {job.root.get()};
        std::set<const SceneNode*> seen;
        std::set<std::string> offFeatures;
        while (!stack.empty()) {
            const SceneNode* node = stack.back();
            stack.pop_back();
            if (!seen.insert(node).second) continue;
            if (node->compound && !features.enabled(node->compound->feature()))
                offFeatures.insert(node->compound->feature());
            for (const auto& child : node->children) stack.push_back(child.get());
        }
        // Compound nodes that are surely empty (a difference of empty groups).
        std::map<const SceneNode*, bool> done;
        leavesShapes(*job.root, features, job.where, done, warnings);
        if (offFeatures.count("csg"))
            warnings.push_back(job.where + ": the scene's CSG nodes (gr.union, gr.intersection, " +
                               "gr.difference, node:csg) are drawn as plain groups of their " +
                               "operands: they need chapter 14 (csg), and " +
                               whyAbsent(features, "csg", 14));
    }
    // The course framework writes PNG data whatever the name says; so does rt, but says so.
    // A name a switched-on chapter writes in its own format (chapter 12's .hdr) is not PNG.
    if (!hasPngExtension(output) && !outputFormatFor(features.on(), output))
        warnings.push_back(job.where + ": the output '" + output +
                           "' does not end in .png; rt writes a PNG image under that name, as " +
                           "the course framework does");
    return warnings;
}

std::vector<std::string> energyWarnings(const RenderJob& job,
                                        const std::vector<Instance>& instances) {
    std::vector<std::string> warnings;
    std::set<const Material*> seen;
    for (const Instance& i : instances) {
        const Material* m = i.material;
        if (!m || !seen.insert(m).second) continue;
        // The opaque part's shares, as the path tracer reads them (src/path_tracing/bsdf.cpp).
        const Colour total = glm::max(m->kd, Colour(0.0)) + glm::max(m->ks, Colour(0.0)) +
                             Colour(std::max(0.0, m->param("reflect")));
        const double largest = std::max({total.r, total.g, total.b});
        if (!(largest > 1.0)) continue;
        char sum[32];
        std::snprintf(sum, sizeof sum, "%.3g", largest);
        warnings.push_back(job.where + ": the material of '" + i.name +
                           "' reflects more light than it receives (kd + ks + reflect = " + sum +
                           " in its brightest channel); path tracing scales it down by that much");
    }
    return warnings;
}

}  // namespace rb
