#include "path_tracing/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/material.h"
#include "path_tracing/bsdf.h"
#include "phong/phong.h"
#include "reflection/reflection.h"
#include "refraction/refraction.h"

namespace rb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The largest channel.
double maxChannel(const Colour& c) {
    return std::max({c.r, c.g, c.b});
}

}  // namespace

// [power-heuristic]
double powerHeuristic(double pdfA, double pdfB) {
    // [exercise-power-heuristic]
    // Exercise 18.1, the MIS weight: read ch18-mis.
    // Blank: return 0.5;
    if (std::isinf(pdfA)) return 1.0;
    const double a = pdfA * pdfA, b = pdfB * pdfB;
    return a + b > 0.0 ? a / (a + b) : 0.0;
    // [exercise-power-heuristic]
}
// [power-heuristic]

/// A point where the path scatters: on a surface (with its BSDF) or at a particle of a medium.
struct PathTracer::Vertex {
    Vec3 p{0.0};                 ///< Where the light is reflected.
    Vec3 shadowOrigin{0.0};      ///< Where its shadow rays start.
    const Bsdf* bsdf = nullptr;  ///< A surface's BSDF, or null at a particle.
    const MediaTerm* media = nullptr;
    double g = 0.0;    ///< A particle's phase asymmetry.
    Vec3 travel{0.0};  ///< The direction the path arrived in (unit).

    /// What the vertex sends back along the path of the light arriving from unit wi: f·cos θi
    /// on a surface, the phase function at a particle.
    Colour scatter(const Vec3& wi) const {
        if (bsdf) return bsdf->f(wi) * std::abs(glm::dot(wi, bsdf->n()));
        return Colour(media->phase(g, travel, wi));
    }
    /// The density with which the path's own sampling would draw wi.
    double pdf(const Vec3& wi) const { return bsdf ? bsdf->pdf(wi) : media->phase(g, travel, wi); }
};

void PathTracer::run(const Scene& scene, const Pipeline& pipeline, const PrePassContext&) {
    emitters_ = std::make_unique<Emitters>(scene.instances);
    for (const auto& term : pipeline.terms) {
        if (dynamic_cast<const ReflectionTerm*>(term.get())) mirrors_ = true;
        if (const auto* r = dynamic_cast<const RefractionTerm*>(term.get())) refraction_ = r;
    }
    lobe_ = pipeline.lobe.get();
}

std::string PathTracer::statistics() const {
    return std::string("path tracing: ") +
           (emitters_ && emitters_->sampleable() ? "emitting surfaces sampled, "
                                                 : "no emitting surface sampled, ") +
           "depth " + std::to_string(settings_.maxDepth) + ", roulette from bounce " +
           std::to_string(settings_.rouletteDepth) + ", " +
           (settings_.strategy == PathStrategy::Mis     ? "MIS"
            : settings_.strategy == PathStrategy::Light ? "light sampling only"
                                                        : "BSDF sampling only");
}

// [direct-light]
Colour PathTracer::directLight(const Integrator& integrator, const Vertex& v, Sampler& sampler,
                               RayCounters& counters) const {
    const Scene& scene = integrator.scene();
    Colour L(0.0);
    // Step 1: A4's point lights and chapter 6's area lights, one point of each. They are in
    // units where a white diffuse surface returns I cos θ / r², π times a physical point
    // light's, so the physical BSDF (kd/π for Lambert) is multiplied by π.
    for (const PointLight& light : scene.lights) {
        double emission = 1.0;
        const Vec3 from =
            light.shape && scene.sampleAreaLights
                ? light.shape->samplePoint(light.position, v.p, 0, 1, sampler.next2D(), emission)
                : light.position;
        const Vec3 toLight = from - v.p;
        const double r = glm::length(toLight);
        if (!(r > 0.0) || emission <= 0.0) continue;
        const Colour f = v.scatter(toLight / r);
        if (f == Colour(0.0)) continue;
        if (integrator.occluded(Ray{v.shadowOrigin, from - v.shadowOrigin}, 1.0, counters))
            continue;
        Colour Ld = kPi * emission * light.intensityAt(r) * f;
        if (integrator.hasMedia()) Ld *= integrator.transmittance(v.p, from, sampler, counters);
        L += Ld;
    }
    // Step 2: one point on one emitting surface, by area, weighed against the path's own
    // sampling of the same direction.
    if (settings_.strategy == PathStrategy::Bsdf || !emitters_ || !emitters_->sampleable())
        return L;
    // [exercise-light-sampling]
    // Exercise 18.4, light sampling in solid angle: read ch18-nee.
    // Blank: return L;
    const double u = sampler.next1D();
    const EmitterSample e = emitters_->sample(u, sampler.next2D());
    const Vec3 toLight = e.p - v.p;
    const double distance2 = glm::dot(toLight, toLight);
    if (!(distance2 > 0.0)) return L;
    const Vec3 wi = toLight / std::sqrt(distance2);
    // An emitting surface emits on both sides, like a sheet of glowing paper.
    const double cosLight = std::abs(glm::dot(e.n, wi));
    if (!(cosLight > 0.0)) return L;
    // The area density turned into a density per steradian at the vertex.
    const double pdfLight = e.pdfArea * distance2 / cosLight;
    const Colour f = v.scatter(wi);
    if (f == Colour(0.0)) return L;
    const Vec3 target = offsetRayOrigin(e.p, e.n, -wi);  // on the vertex's side of the emitter
    if (integrator.occluded(Ray{v.shadowOrigin, target - v.shadowOrigin}, 1.0, counters)) return L;
    const double weight =
        settings_.strategy == PathStrategy::Mis ? powerHeuristic(pdfLight, v.pdf(wi)) : 1.0;
    Colour Ld = f * e.Le * (weight / pdfLight);
    if (integrator.hasMedia()) Ld *= integrator.transmittance(v.p, e.p, sampler, counters);
    return L + Ld;
    // [exercise-light-sampling]
}
// [direct-light]

// [roulette]
bool PathTracer::survivesRoulette(int depth, Colour& beta, Sampler& sampler) const {
    if (depth + 1 < settings_.rouletteDepth) return true;
    // A path whose throughput has fallen below 1 goes on with probability q = its largest
    // channel and, if it does, carries 1/q more: the mean is unchanged, and a survivor's
    // throughput is back to 1 (so its weight never grows past what it started with).
    const double q = maxChannel(beta);
    if (q >= 1.0) return true;
    if (!(q > 0.0) || sampler.next1D() >= q) return false;
    beta /= q;
    return true;
}
// [roulette]

// [path-loop]
Colour PathTracer::Li(const Integrator& integrator, const Ray& cameraRay, Sampler& sampler,
                      RayCounters& counters) const {
    const Scene& scene = integrator.scene();
    const Pipeline& pipeline = integrator.pipeline();
    Colour L(0.0), beta(1.0);
    Ray ray = cameraRay;
    MediumStack media = kNoMedia;
    // What the last bounce was: a delta (or the camera), so emitters it hits count in full,
    // or a sampled direction with density lastPdf from lastP.
    bool lastDelta = true;
    double lastPdf = 0.0;
    for (int depth = 0;; ++depth) {
        Hit hit;
        const bool found = scene.aggregate->intersect(ray, kInfinity, hit);
        // Step 1: the media along the ray (chapter 17) may scatter the path first.
        if (pipeline.media) {
            const ShadeContext ctx{scene, integrator, sampler, counters, depth, media, 1.0, false};
            MediaTerm::Interaction particle;
            if (pipeline.media->sampleInteraction(ctx, ray, found ? hit.t : kInfinity, beta,
                                                  particle)) {
                if (!(maxChannel(beta) > 0.0) || depth + 1 >= settings_.maxDepth) break;
                Vertex v;
                v.p = v.shadowOrigin = particle.x;
                v.media = pipeline.media.get();
                v.g = particle.g;
                v.travel = glm::normalize(ray.d);
                L += beta * directLight(integrator, v, sampler, counters);
                // The phase function is its own pdf: the weight is 1.
                const Vec3 wi = v.media->samplePhase(v.g, v.travel, sampler.next2D());
                lastPdf = v.media->phase(v.g, v.travel, wi);
                lastDelta = false;
                ray = Ray{particle.x, wi};
                counters.add(RayKind::Scatter);
                if (!survivesRoulette(depth, beta, sampler)) break;
                continue;
            }
        }
        // Step 2: the path leaves the scene: the background is its light.
        if (!found) {
            L += beta * scene.background;
            break;
        }
        // Step 3: light the surface emits towards the path (on either side).
        for (const auto& normal : pipeline.normals) normal->apply(ray, hit);
        if (!hit.material) break;
        const Material textured = pipeline.textureLookup && !hit.material->textures.empty()
                                      ? pipeline.textureLookup(hit)
                                      : Material{};
        const Material& m =
            pipeline.textureLookup && !hit.material->textures.empty() ? textured : *hit.material;
        const double rayLength = glm::length(ray.d);
        const Vec3 wo = -ray.d / rayLength;
        const double cosEmitter = std::abs(glm::dot(wo, hit.ng));
        if (hit.material->emission != Colour(0.0)) {
            double weight = 1.0;
            if (!lastDelta && settings_.strategy != PathStrategy::Bsdf) {
                // Light sampling could have found this point too: weigh by MIS, or leave it
                // to light sampling alone.
                const double distance = hit.t * rayLength;
                const double pdfLight =
                    emitters_ ? emitters_->pdfArea(hit.instance) * distance * distance / cosEmitter
                              : 0.0;
                if (settings_.strategy == PathStrategy::Light && pdfLight > 0.0)
                    weight = 0.0;
                else
                    weight = powerHeuristic(lastPdf, pdfLight);
            }
            L += weight * beta * hit.material->emission;
        }
        if (depth + 1 >= settings_.maxDepth) break;
        // Step 4: light sampling at the surface, then the BSDF's own direction.
        const Bsdf bsdf(hit, m, wo, mirrors_, refraction_, lobe_);
        if (bsdf.hasSmoothPart()) {
            Vertex v;
            v.p = hit.p;
            v.shadowOrigin = offsetRayOrigin(hit.p + hit.shadowOffset, bsdf.ng(), bsdf.n());
            v.bsdf = &bsdf;
            L += beta * directLight(integrator, v, sampler, counters);
        }
        BsdfSample s;
        if (!bsdf.sample(sampler, media, s)) break;
        beta *= s.weight;
        lastDelta = s.delta;
        lastPdf = s.pdf;
        if (s.transmitted) media = s.media;
        ray = Ray{offsetRayOrigin(hit.p, hit.ng, s.wi), s.wi};
        counters.add(RayKind::Path);
        if (!survivesRoulette(depth, beta, sampler)) break;
    }
    return L;
}
// [path-loop]

}  // namespace rb
