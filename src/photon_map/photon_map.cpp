#include "photon_map/photon_map.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/material.h"
#include "core/render_context.h"
#include "lab/warp.h"
#include "phong/phong.h"

namespace rb {

void bindPhotonMap(LuaBindings& lua);

namespace {

/// The first radius, in pixel footprints at the typical distance the camera sees: the caustic
/// map's, and the indirect map's (its photons are spread over the whole scene, so it needs a
/// wider disk to find as many).
constexpr double kCausticFootprints = 3.0;
constexpr double kIndirectFootprints = 12.0;

/// A whole number from the command line within [lo, hi], or InputError naming the option.
double cliNumber(const RenderContext& context, const char* option, double lo, double hi,
                 bool integer, double fallback) {
    const std::string text = context.cliOption(option);
    if (text.empty()) return fallback;
    const double v = parseNumberOption(std::string("--") + option, text);
    if (v < lo || v > hi || (integer && v != std::floor(v)))
        throw InputError(std::string("--") + option + ": expected " +
                         (integer ? "a whole number" : "a number") + " from " + formatNumber(lo) +
                         " to " + formatNumber(hi) + ", got " + text);
    return v;
}

}  // namespace

// [photon-settings]
PhotonSettings photonSettings(const RenderContext& context) {
    PhotonSettings s;
    // The scene's gr.photons{...} (checked when it was called).
    s.on = context.sceneOption("photons", 0.0) != 0.0;
    s.photons = static_cast<std::uint64_t>(context.sceneOption("photon_count", 20000));
    s.passes = static_cast<int>(context.sceneOption("photon_passes", s.passes));
    s.radius = context.sceneOption("photon_radius", 0.0);
    s.alpha = context.sceneOption("photon_alpha", s.alpha);
    s.classic = context.sceneOption("photon_classic", 0.0) != 0.0;
    s.nearest = static_cast<int>(context.sceneOption("photon_nearest", 0.0));
    s.atLeast = static_cast<int>(context.sceneOption("photon_at_least", 0.0));
    s.caustics = context.sceneOption("photon_caustics", 1.0) != 0.0;
    s.indirect = context.sceneOption("photon_indirect", 0.0) != 0.0;
    s.gather = static_cast<int>(context.sceneOption("photon_gather", s.gather));
    // The command line overrides it; --photons alone switches photon mapping on.
    if (!context.cliOption("photons").empty()) s.on = true;
    s.photons = static_cast<std::uint64_t>(
        cliNumber(context, "photons", 1, 1e12, true, static_cast<double>(s.photons)));
    s.passes = static_cast<int>(cliNumber(context, "photon-passes", 1, 100000, true, s.passes));
    s.radius = cliNumber(context, "photon-radius", 1e-12, 1e12, false, s.radius);
    s.alpha = cliNumber(context, "photon-alpha", 1e-6, 1.0 - 1e-6, false, s.alpha);
    s.gather = static_cast<int>(cliNumber(context, "photon-gather", 0, 65536, true, s.gather));
    s.atLeast =
        static_cast<int>(cliNumber(context, "photon-at-least", 0, 1e6, true, s.atLeast));
    return s;
}
// [photon-settings]

std::vector<double> passRadii(double r0, double alpha, int passes, bool classic) {
    std::vector<double> radii(static_cast<std::size_t>(passes), r0);
    if (classic) return radii;
    // [exercise-radius]
    // Exercise 16.1, the shrinking radius: read ch16-progressive.
    // Blank: return radii;
    // Source: C. Knaus and M. Zwicker, "Progressive Photon Mapping: A Probabilistic Approach",
    // ACM TOG 30(3), 2011, eq. 19: r²_{i+1} = r²_i (i + α)/(i + 1), passes counted from 1.
    for (int i = 1; i < passes; ++i) radii[i] = radii[i - 1] * std::sqrt((i + alpha) / (i + 1.0));
    return radii;
    // [exercise-radius]
}

Colour irradianceEstimate(const Colour& flux, double radius) {
    // [exercise-density]
    // Exercise 16.2, the density estimate: read ch16-estimate.
    // Blank: return Colour(0.0);
    return flux / (M_PI * radius * radius);
    // [exercise-density]
}

// [irradiance]
Colour PhotonPasses::passIrradiance(const Vec3& x, const Vec3& n, int nearest,
                                    std::size_t pass) const {
    if (grids.empty()) return Colour(0.0);
    const PhotonGrid& grid = grids[pass % grids.size()];
    const double r = radii[pass % grids.size()];
    double r2 = 0.0;
    if (nearest > 0) {
        const Colour flux = grid.gatherNearest(x, n, nearest, r2);
        return r2 > 0.0 ? irradianceEstimate(flux, std::sqrt(r2)) : Colour(0.0);
    }
    int count = 0;
    const Colour flux = grid.gatherFlux(x, n, r, &count);
    if (count < atLeast && !wide.empty()) {
        // Too few photons for a smooth estimate: the disk grows to hold atLeast of them, in
        // the pass's wide grid (PhotonGrid::gatherNearer).
        const Colour grown = wide[pass % wide.size()].gatherNearer(x, n, atLeast, r2);
        return r2 > 0.0 ? irradianceEstimate(grown, std::sqrt(r2)) : Colour(0.0);
    }
    return irradianceEstimate(flux, r);
}

Colour PhotonPasses::irradiance(const Vec3& x, const Vec3& n, int nearest) const {
    if (grids.empty()) return Colour(0.0);
    Colour sum(0.0);
    for (std::size_t i = 0; i < grids.size(); ++i) sum += passIrradiance(x, n, nearest, i);
    return sum / static_cast<double>(grids.size());
}
// [irradiance]

// [photon-term]
Colour PhotonMapping::apply(const ShadeContext& ctx, const Ray& ray, const Hit& hit,
                            const Colour& colour) const {
    if (!hit.material) return colour;
    const Material& m = ctx.integrator.pipeline().textureLookup && !hit.material->textures.empty()
                            ? ctx.integrator.pipeline().textureLookup(hit)
                            : *hit.material;
    // The opaque part of the surface is diffuse; chapter 5's transparent part is glass.
    const double transparency = glass_ ? hit.material->param("transparency") : 0.0;
    if (m.kd == Colour(0.0) || transparency >= 1.0) return colour;
    // The gather looks at the side the ray sees.
    const Vec3 n = faceForward(hit.ns, -ray.d);
    Colour e = caustics_.irradiance(hit.p, n, settings_.nearest);
    // The indirect light: a final gather over the hemisphere, or the map read right here.
    if (settings_.gather > 0 && !indirect_.grids.empty())
        e += gatherIrradiance(ctx, hit, n, settings_.gather);
    else
        e += indirect_.irradiance(hit.p, n, settings_.nearest);
    return colour + (1.0 - std::clamp(transparency, 0.0, 1.0)) * m.kd * e;
}
// [photon-term]

std::uint64_t photonPassBytes(std::uint64_t photons, bool wide) {
    // Per record: the pass's chunks, the merged list, the grid's sorted copy, its bucket of
    // each photon and its table; and the wide grid's copy and table when gathers grow.
    const std::uint64_t grid = sizeof(Photon) + PhotonGrid::bytesPerPhoton();
    const std::uint64_t perRecord =
        2 * sizeof(Photon) + sizeof(std::uint32_t) + (wide ? 2 : 1) * grid;
    return saturatingProduct(saturatingProduct(photons, kMaxStoredPerPhoton), perRecord);
}

namespace {

/// The distance the camera typically sees (the median over a 16 × 16 grid of camera rays that
/// hit something) times the angle one pixel spans: the width of a pixel there.
double pixelFootprint(const Scene& scene, const PrePassContext& ctx) {
    std::vector<double> distances;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
            const Ray ray =
                ctx.camera.generateRay((i + 0.5) * ctx.width / 16.0, (j + 0.5) * ctx.height / 16.0);
            Hit hit;
            if (scene.aggregate->intersect(ray, std::numeric_limits<double>::infinity(), hit))
                distances.push_back(hit.t * glm::length(ray.d));
        }
    const Ray a = ctx.camera.generateRay(0.5 * ctx.width, 0.5 * ctx.height);
    const Ray b = ctx.camera.generateRay(0.5 * ctx.width + 1.0, 0.5 * ctx.height);
    const double pixelAngle =
        std::acos(std::clamp(glm::dot(glm::normalize(a.d), glm::normalize(b.d)), -1.0, 1.0));
    if (distances.empty()) return 0.0;
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    return distances[distances.size() / 2] * pixelAngle;
}

}  // namespace

// [photon-passes]
void PhotonMapping::run(const Scene& scene, const Pipeline& pipeline, const PrePassContext& ctx) {
    const auto start = std::chrono::steady_clock::now();
    const PhotonScattering scattering = PhotonScattering::of(pipeline);
    scattering_ = scattering;
    glass_ = scattering.refraction != nullptr;
    // Step 1: the first radius, from the pixel footprint unless the scene gave one.
    const double footprint = pixelFootprint(scene, ctx);
    if (settings_.radius == 0.0 && !(footprint > 0.0)) return;  // the camera sees nothing
    const double causticR0 =
        settings_.radius > 0.0 ? settings_.radius : kCausticFootprints * footprint;
    const double indirectR0 =
        settings_.radius > 0.0 ? settings_.radius : kIndirectFootprints * footprint;
    // Step 2: each pass of each map emits new photons, from its own random streams. Passes
    // trace together, in one parallel loop, as many at a time as the memory budget holds
    // (photonPassBytes bounds each): usually all. A pass that does not fit alone is refused
    // before any of its photons is traced.
    struct MapPasses {
        PhotonPaths paths;
        double r0;
        PhotonPasses* map;
    };
    std::vector<MapPasses> maps;
    if (settings_.caustics) maps.push_back({PhotonPaths::Caustic, causticR0, &caustics_});
    if (settings_.indirect) maps.push_back({PhotonPaths::Indirect, indirectR0, &indirect_});
    std::vector<PhotonTraceSettings> passes;
    for (const MapPasses& m : maps)
        for (int pass = 0; pass < settings_.passes; ++pass) {
            PhotonTraceSettings trace;
            trace.paths = m.paths;
            trace.photons = settings_.photons;
            trace.pass = pass;
            trace.seed = ctx.seed;
            trace.cluster = ctx.cluster;
            passes.push_back(trace);
        }
    const std::uint64_t each = photonPassBytes(settings_.photons, settings_.atLeast > 0);
    std::vector<std::vector<Photon>> traced;
    while (traced.size() < passes.size()) {
        const std::size_t first = traced.size();
        std::size_t last = first + 1;
        if (ctx.memory) {
            const std::uint64_t free = ctx.memory->available();
            if (each > free)
                throw InputError(ctx.memory->refusal(
                    each, free, where_,
                    "photon pass " + std::to_string(passes[first].pass + 1) + " (" +
                        std::to_string(settings_.photons) + " photons)"));
            while (last < passes.size() && (last - first + 1) <= free / each) ++last;
        } else {
            last = passes.size();
        }
        auto batch = tracePhotonPasses(
            scene, scattering, {passes.begin() + first, passes.begin() + last}, ctx.counters);
        for (auto& photons : batch) traced.push_back(std::move(photons));
    }
    // Step 3: each pass's photons sorted into a grid sized for that pass's radius. The grids
    // do not depend on one another, so they are built side by side, the largest first.
    std::vector<std::pair<PhotonPasses*, int>> grids;
    for (std::size_t m = 0; m < maps.size(); ++m) {
        PhotonPasses& map = *maps[m].map;
        map.radii = passRadii(maps[m].r0, settings_.alpha, settings_.passes, settings_.classic);
        map.atLeast = settings_.atLeast;
        if (map.atLeast > 0) map.wide.resize(settings_.passes);
        map.grids.resize(settings_.passes);
        for (int pass = 0; pass < settings_.passes; ++pass) {
            map.stored += traced[m * settings_.passes + pass].size();
            grids.push_back({&map, pass});
        }
    }
    std::vector<std::size_t> order(grids.size());
    for (std::size_t g = 0; g < order.size(); ++g) order[g] = g;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return traced[a].size() > traced[b].size();
    });
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(order.size()); ++i) {
        const auto [map, pass] = grids[order[i]];
        // A floor of photons per gather needs a second, wider grid of the same photons.
        if (map->atLeast > 0)
            map->wide[pass] =
                PhotonGrid(traced[order[i]], PhotonGrid::kWidestGrowth * map->radii[pass]);
        map->grids[pass] = PhotonGrid(std::move(traced[order[i]]), map->radii[pass]);
    }
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
// [photon-passes]

std::string PhotonMapping::statistics() const {
    // One map's part of the line: its photons and its first and last radius.
    auto map = [](const char* name, const PhotonPasses& m) {
        if (m.radii.empty()) return std::string();
        char text[128];
        std::snprintf(text, sizeof text, "; %s %llu stored, radius %.4g -> %.4g", name,
                      static_cast<unsigned long long>(m.stored), m.radii.front(), m.radii.back());
        return std::string(text);
    };
    char head[96];
    std::snprintf(head, sizeof head, "photons    %d passes of %llu in %.3f s", settings_.passes,
                  static_cast<unsigned long long>(settings_.photons), seconds_);
    std::string gather;
    if (!indirect_.grids.empty())
        gather = settings_.gather > 0
                     ? "; final gather " + std::to_string(settings_.gather) + " rays"
                     : "; indirect map read directly";
    return head + map("caustic", caustics_) + map("indirect", indirect_) + gather;
}

namespace {

// [install-photon-map]
void installPhotonMap(Pipeline& pipeline, Scene& scene, const RenderContext& context) {
    // Read (and check) the settings for every scene, so a bad value always fails the same way.
    const PhotonSettings settings = photonSettings(context);
    // A scene that asks for no photons pays nothing: no term, no pass.
    if (!settings.on || (!settings.caustics && !settings.indirect)) return;
    // The indirect map measures the light that A4's ambient term stands in for: drop it.
    if (settings.indirect) scene.ambient = Colour(0.0);
    auto mapping = std::make_shared<PhotonMapping>(settings, context.job.where);
    pipeline.terms.push_back(mapping);
    pipeline.prePasses.push_back(mapping);
}
// [install-photon-map]

}  // namespace

/// The chapter's samplers for ./rt --warptest (emission_warps.cpp).
std::vector<Warp> photonEmissionWarps();

Feature photonMapFeature() {
    return {"photon_map",
            16,
            "photon mapping: caustics and indirect light, progressive (radius shrinks by alpha)",
            true,
            bindPhotonMap,
            installPhotonMap,
            {{"photons", "N", "photons per pass for each map; switches photon mapping on",
              "the scene's gr.photons, else 20000 (off without either)"},
             {"photon-passes", "N", "photon passes, each with new photons and a smaller radius",
              "the scene's, else 16"},
             {"photon-radius", "R", "the first pass's gather radius, in scene units",
              "the scene's, else 3 (caustics) or 12 (indirect) pixel footprints"},
             {"photon-alpha", "A", "radius shrink per pass, in (0, 1)", "the scene's, else 2/3"},
             {"photon-gather", "N",
              "final gather rays for the indirect light at each visible point (0: read the "
              "indirect map there directly)",
              "the scene's, else 32"},
             {"photon-at-least", "M",
              "where fewer than M photons lie within a gather's radius, grow the disk to hold M "
              "(up to 3 radii; 0: never)",
              "the scene's, else 0"}},
            {},
            photonEmissionWarps};
}

}  // namespace rb
