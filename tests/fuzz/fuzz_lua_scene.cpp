/// \file
/// Fuzz target: a scene script from text to built scenes, the way ./rt runs it up to the
/// render: the sandboxed Lua loader with every chapter's calls (src/core/lua_scene.cpp,
/// lua_a4.cpp, the chapters' lua_*.cpp), then for each gr.render the image-size check, the
/// camera, the render warnings and buildWorld (features installed, meshes and BVH built).
/// Nothing is rendered and nothing is written: gr.render only records a request.
///
/// The script runs as if it were scenes/fuzz-input.lua (the file need not exist: the text is
/// handed over in SceneLoadOptions::sceneText), so gr.mesh, require and the read-only io find
/// the project's own meshes in scenes/, scenes/a4, scenes/legacy and scenes/assets.
/// A line `-- rt-args: ...` (as in the bad-input cases) switches on --lenient, --legacy or
/// --modern for that input, so the fuzzer reaches those paths too.
/// Limits are smaller than ./rt's, so one input stays well under libFuzzer's -timeout and
/// -rss_limit_mb: 5 million Lua instructions and 64 MiB of Lua memory.
#include <cstddef>
#include <cstdint>
#include <string>

#include "app/render_warnings.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/image.h"
#include "core/world.h"
#include "scene/lua_scene.h"

namespace {

/// The fuzz run's load options: the scene's folder, the asset folders and the smaller limits.
rb::SceneLoadOptions fuzzLoadOptions() {
    rb::SceneLoadOptions options;
    options.instructionLimit = 5'000'000;
    options.memoryLimit = std::size_t(64) << 20;
    options.assetDirs = {RB_SOURCE_DIR "/scenes/a4", RB_SOURCE_DIR "/scenes/legacy",
                         RB_SOURCE_DIR "/scenes/assets"};
    return options;
}

/// Apply the --lenient, --legacy and --modern named on a `-- rt-args:` line of the script.
void applyRtArgs(const std::string& text, rb::SceneLoadOptions& options) {
    const std::size_t at = text.find("-- rt-args:");
    if (at == std::string::npos) return;
    const std::string line = text.substr(at, text.find('\n', at) - at);
    options.lenient = line.find("--lenient") != std::string::npos;
    if (line.find("--legacy") != std::string::npos)
        options.era = rb::EraChoice::Legacy;
    else if (line.find("--modern") != std::string::npos)
        options.era = rb::EraChoice::Modern;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Empty text would mean "read the file" to the loader; an empty scene is uninteresting.
    if (size == 0) return 0;
    static const std::vector<rb::Feature> built = rb::builtFeatures();
    static const rb::FeatureSet features(built, "all");
    rb::SceneLoadOptions options = fuzzLoadOptions();
    options.sceneText.assign(reinterpret_cast<const char*>(data), size);
    applyRtArgs(options.sceneText, options);
    try {
        std::vector<rb::LoadedRender> renders =
            rb::loadScene(RB_SOURCE_DIR "/scenes/fuzz-input.lua", features, options);
        for (rb::LoadedRender& r : renders) {
            const rb::RenderJob& job = r.job;
            rb::checkImageSize(job.width, job.height, job.where + ": ");
            const std::unique_ptr<rb::World> world = rb::buildWorld(std::move(r), features);
            const rb::RenderJob& built_job = world->source.job;
            const rb::PinholeCamera camera(built_job.camera, built_job.width, built_job.height);
            rb::renderWarnings(built_job, world->scene.instances, camera, features,
                               "fuzz-output.png");
        }
    } catch (const rb::InputError&) {
        // Bad input, reported as it should be.
    }
    return 0;
}
