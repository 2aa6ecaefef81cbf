#include "core/world.h"

#include <string>
#include <string_view>

#include "core/error.h"
#include "core/render_context.h"

namespace rb {

// [build-world]
std::unique_ptr<World> buildWorld(LoadedRender render, const FeatureSet& features,
                                  const std::map<std::string, std::string>& featureOptions,
                                  int maxDepth) {
    auto world = std::make_unique<World>();
    world->source = std::move(render);
    const RenderJob& job = world->source.job;
    Scene& scene = world->scene;
    // The instances, lights and settings the script asked for.
    scene.instances = std::move(world->source.instances);
    scene.lights = job.lights;
    scene.ambient = job.ambient;
    auto depth = job.options.find("max_depth");
    if (depth != job.options.end()) scene.maxDepth = static_cast<int>(depth->second);
    if (maxDepth >= 0) scene.maxDepth = maxDepth;
    auto minWeight = job.options.find("min_weight");
    if (minWeight != job.options.end()) scene.minWeight = minWeight->second;
    // A shape whose chapter is switched off is not drawn, as if the chapter were not written.
    // CSG operands of such a shape were left out while flattening; they count the same.
    std::map<std::string, size_t> hidden = world->source.leftOutOperands;
    std::erase_if(scene.instances, [&](const Instance& i) {
        const char* feature = i.shape->feature();
        if (!feature || features.enabled(feature)) return false;
        ++hidden[feature];
        return true;
    });
    for (const auto& [feature, count] : hidden)
        world->warnings.push_back(job.where + ": " + std::to_string(count) + " shape" +
                                  (count == 1 ? "" : "s") + " of the '" + feature +
                                  "' feature not drawn: --features switched it off");
    // Each enabled chapter plugs itself in, in chapter order; then the aggregate is built.
    const RenderContext context{scene.instances, job, featureOptions};
    for (const Feature& f : features.on()) {
        if (!f.install) continue;
        try {
            f.install(world->pipeline, scene, context);
        } catch (const InputError& e) {
            // Point at the gr.render call whose settings were refused; a command-line option's
            // message ("--photons: ...") is the option's, which no scene line set.
            const bool option = std::string_view(e.what()).starts_with("--");
            throw InputError(job.where.empty() || option ? e.what() : job.where + ": " + e.what());
        }
    }
    // A shape that only bounds a medium is no surface: chapter 17 took what it needs of it,
    // and with chapter 17 off it is not there at all.
    std::erase_if(scene.instances, [](const Instance& i) { return i.mediumBoundaryOnly; });
    scene.aggregate = world->pipeline.buildAggregate(scene.instances);
    return world;
}
// [build-world]

}  // namespace rb
