/// \file
/// make soak's pixel check (tests/soak/soak.sh): renders scene files as rt does, in this
/// process, and looks at the film itself.
///
/// rt's writers store a NaN, infinite or negative channel as 0 (src/core/image.cpp toBytes,
/// src/tone_map/hdr_output.cpp), so no image on disk can show one. This program loads each
/// scene with the --features list given beside it, builds each gr.render's world and renders it
/// on one thread (seed 0, one sample a pixel, the scene's own samplers) with the same calls as
/// src/app/main.cpp. Every channel of the film must be finite and non-negative, and after the
/// post-process (chapter 12's tone map) also at most 1.
///
/// usage: soak_film SCENE.lua FEATURES [SCENE.lua FEATURES ...]
/// Prints "ok SCENE" or "BAD SCENE: why" for each scene, and "checking SCENE" before it, so
/// that a crash names the scene it happened in. Exit code 0 when every scene is ok, 3 when a
/// pixel is not, 1 for a scene rt would refuse (InputError), 2 for a wrong command line.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "core/error.h"
#include "core/feature.h"
#include "core/post_process.h"
#include "core/render.h"
#include "core/world.h"
#include "scene/lua_scene.h"

namespace {

/// `c` with every digit a float holds (std::to_string prints -1e-9 as -0.000000).
std::string exact(float c) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", c);
    return text;
}

/// What is wrong with the image's channels: "" when each is finite, ≥ 0 and at most `most`.
std::string channelFault(const rb::Image& image, float most) {
    const auto data = image.data();
    for (size_t i = 0; i < data.size(); ++i) {
        const float c = data[i];
        const std::string where = " at pixel (" + std::to_string(i / 3 % image.width()) + ", " +
                                  std::to_string(i / 3 / image.width()) + "), channel " +
                                  std::to_string(i % 3);
        if (!std::isfinite(c)) return "a channel is " + exact(c) + where;
        if (c < 0.0f) return "a channel is negative (" + exact(c) + ")" + where;
        if (c > most) return "a display channel exceeds 1 (" + exact(c) + ")" + where;
    }
    return "";
}

/// Render every gr.render of `path` with `features`; "" when every pixel is sound.
std::string checkScene(const std::string& path, const std::string& featureList) {
    const rb::FeatureSet features(rb::builtFeatures(), featureList);
    for (rb::LoadedRender& r : rb::loadScene(path, features, rb::SceneLoadOptions{})) {
        const std::unique_ptr<rb::World> world = rb::buildWorld(std::move(r), features);
        const rb::RenderJob& job = world->source.job;
        const rb::PinholeCamera camera(job.camera, job.width, job.height);
        rb::RenderSettings settings;
        settings.threads = 1;
        rb::RayCounters counters;
        rb::Image image =
            rb::render(world->scene, world->pipeline, camera, job.width, job.height, settings,
                       counters);
        if (std::string fault = channelFault(image, INFINITY); !fault.empty())
            return job.where + ": film: " + fault;
        if (world->pipeline.postProcess) {
            world->pipeline.postProcess->apply(image);
            if (std::string fault = channelFault(image, 1.0f); !fault.empty())
                return job.where + ": after the tone map: " + fault;
        }
    }
    return "";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3 || argc % 2 == 0) {
        std::fprintf(stderr, "usage: soak_film SCENE.lua FEATURES [SCENE.lua FEATURES ...]\n");
        return 2;
    }
    int status = 0;
    for (int i = 1; i + 1 < argc; i += 2) {
        std::printf("checking %s\n", argv[i]);
        std::fflush(stdout);
        try {
            const std::string fault = checkScene(argv[i], argv[i + 1]);
            if (fault.empty()) {
                std::printf("ok %s\n", argv[i]);
            } else {
                std::printf("BAD %s: %s\n", argv[i], fault.c_str());
                status = 3;
            }
        } catch (const rb::InputError& e) {
            std::printf("BAD %s: refused: %s\n", argv[i], e.what());
            if (status == 0) status = 1;
        }
        std::fflush(stdout);
    }
    return status;
}
