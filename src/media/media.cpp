#include "media/media.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/render_context.h"
#include "core/scene_graph.h"
#include "lab/warp.h"

namespace rb {

namespace {

/// The command line's whole number --`name`, checked to lie in [lo, hi]; `fallback` when the
/// option is not given.
int wholeOption(const RenderContext& context, const std::string& name, long lo, long hi,
                int fallback) {
    const std::string text = context.cliOption(name);
    if (text.empty()) return fallback;
    const double n = parseNumberOption("--" + name, text);
    if (!(n >= lo && n <= hi && n == std::floor(n)))
        throw InputError("--" + name + ": expected a whole number from " + std::to_string(lo) +
                         " to " + std::to_string(hi) + ", got " + text);
    return static_cast<int>(n);
}

}  // namespace

MediaSettings mediaSettings(const RenderContext& context) {
    MediaSettings s;
    const std::string method = context.cliOption("media", "track");
    if (method != "track" && method != "march")
        throw InputError("--media: expected 'track' or 'march', got '" + method + "'");
    s.march = method == "march";
    const std::string shadows = context.cliOption("media-shadows", "exact");
    if (shadows == "exact")
        s.shadows = TransmittanceMethod::Exact;
    else if (shadows == "ratio")
        s.shadows = TransmittanceMethod::Ratio;
    else if (shadows == "delta")
        s.shadows = TransmittanceMethod::Delta;
    else
        throw InputError("--media-shadows: expected 'exact', 'ratio' or 'delta', got '" + shadows +
                         "'");
    const std::string direct = context.cliOption("media-direct", "mis");
    if (direct == "mis")
        s.direct = MediaDirect::Mis;
    else if (direct == "flight")
        s.direct = MediaDirect::FreeFlight;
    else if (direct == "light")
        s.direct = MediaDirect::LightPoints;
    else
        throw InputError("--media-direct: expected 'mis', 'flight' or 'light', got '" + direct +
                         "'");
    s.points = wholeOption(context, "media-points", 1, 1024, s.points);
    const std::string near = context.cliOption("media-near-flights", "on");
    if (near != "on" && near != "off")
        throw InputError("--media-near-flights: expected 'on' or 'off', got '" + near + "'");
    s.nearFlights = near == "on";
    // The pixel's samples: --spp, else the scene's antialiasing (chapter 8's gr.antialias),
    // else 1. A pixel's rays share its points, but each takes at least one: with fewer than one
    // a ray, a pixel's single scattering would rest on its 64 points however many samples it
    // took (the plume's error stopped near 0.005 from 144 samples on; one point a ray reaches
    // the same error in about half the time, and goes on falling).
    double samples = 1.0;
    const std::string spp = context.cliOption("spp");
    if (!spp.empty())
        samples = parseNumberOption("--spp", spp);
    else if (context.sceneOption("aa_sampler", 0.0) != 0.0)
        samples = context.sceneOption("aa_samples", 4.0);
    s.pointsPerRay = std::max(1.0, std::round(s.points / std::max(1.0, samples)));
    const std::string step = context.cliOption("media-step");
    if (!step.empty()) {
        s.step = parseNumberOption("--media-step", step);
        if (!(s.step > 0.0)) throw InputError("--media-step: must be > 0, got " + step);
    }
    // Scatterings: --media-bounces, else the scene's gr.option('media_bounces', n), else no cap
    // a scene meets (kMaxMediaBounces).
    s.bounces = static_cast<int>(context.sceneOption("media_bounces", s.bounces));
    s.bounces = wholeOption(context, "media-bounces", 0, kMaxMediaBounces, s.bounces);
    s.majorantResolution = wholeOption(context, "media-majorant", 1, 128, s.majorantResolution);
    return s;
}

namespace {

/// Where fog ends: around every surface, medium boundary, light and the eye, with half the
/// size again on each side. Beyond it a ray reaches the background.
AABB fogBounds(const std::vector<Instance>& instances, const Scene& scene, const RenderJob& job) {
    AABB box;
    for (const Instance& i : instances)
        if (isFinite(i.worldBounds.lo) && isFinite(i.worldBounds.hi)) {
            box.extend(i.worldBounds.lo);
            box.extend(i.worldBounds.hi);
        }
    for (const PointLight& light : scene.lights) box.extend(light.position);
    box.extend(job.camera.eye);
    const Vec3 pad = 0.5 * (box.hi - box.lo) + Vec3(1e-3);
    return AABB{box.lo - pad, box.hi + pad};
}

// [install-media]
void installMedia(Pipeline& pipeline, Scene& scene, const RenderContext& context) {
    MediaSettings settings = mediaSettings(context);
    std::vector<Instance> boundaries;
    for (const Instance& i : scene.instances)
        if (i.medium) boundaries.push_back(i);
    const Medium* fog = context.job.fog.get();
    // A scene without media pays nothing: no term.
    if (boundaries.empty() && !fog) return;
    // Nested media come later in the scene graph's order, and win inside.
    std::stable_sort(
        boundaries.begin(), boundaries.end(),
        [](const Instance& a, const Instance& b) { return a.mediumIndex < b.mediumIndex; });
    const AABB box = fogBounds(scene.instances, scene, context.job);
    // Every instance's bounds, so that a medium's boundary can tell whether it is lone.
    std::vector<AABB> everything;
    for (const Instance& i : scene.instances) everything.push_back(i.worldBounds);
    // A shape that only bounds a medium is no surface.
    std::erase_if(scene.instances, [](const Instance& i) { return i.mediumBoundaryOnly; });
    if (settings.step == 0.0) settings.step = glm::length(box.hi - box.lo) / 400.0;
    pipeline.media =
        std::make_shared<ParticipatingMedia>(std::move(boundaries), fog, box, settings, everything);
}
// [install-media]

}  // namespace

/// The chapter's samplers for ./rt --warptest (media_warps.cpp).
std::vector<Warp> mediaWarps();

Feature mediaFeature() {
    return {"media",
            17,
            "participating media: fog, light shafts and smoke (delta and ratio tracking)",
            true,
            bindMedia,
            installMedia,
            {{"media", "track|march",
              "free flights by delta tracking, or ray marching (single scattering only)", "track"},
             {"media-shadows", "exact|ratio|delta",
              "transmittance through heterogeneous media: exact through voxel grids (else "
              "ratio tracking), ratio or delta tracking",
              "exact"},
             {"media-direct", "mis|flight|light",
              "single scattering in homogeneous media: free flights, lamp points, or both by MIS",
              "mis"},
             {"media-points", "N",
              "lamp points per lamp per pixel, shared by its samples, at least one each (1 to "
              "1024)",
              "64"},
             {"media-step", "S", "ray-marching step, in scene units",
              "1/400 of the scene's size (fog box diagonal)"},
             {"media-majorant", "N", "majorant grid cells per axis (1 to 128)", "16"},
             {"media-bounces", "N", "scatterings after the first (0: single scattering)",
              "the scene's media_bounces, else 1000000 (no cap a scene meets)"},
             {"media-near-flights", "on|off",
              "a walk's flight that ends deep inside a lone homogeneous medium skips the scene "
              "(off: every flight asks it; the same image, slower)",
              "on"}},
            {},
            mediaWarps};
}

}  // namespace rb
