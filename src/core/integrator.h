/// \file
/// The integrator: trace a ray, find the surface, and add up the shading terms.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/aggregate.h"
#include "core/light.h"
#include "core/medium_stack.h"
#include "core/pre_pass.h"
#include "core/sampler.h"
#include "core/stats.h"

namespace rb {

/// The world a ray is traced in: instances, their aggregate, lights and render settings.
struct Scene {
    std::vector<Instance> instances;
    std::unique_ptr<Aggregate> aggregate;
    std::vector<PointLight> lights;
    Colour ambient{0.0};
    Colour background{0.0};
    int maxDepth = 5;      ///< Recursion limit for secondary rays (chapters 4–7).
    int lightSamples = 0;  ///< Samples per axis for every area light (0: each light's own).
    bool sampleAreaLights = false;  ///< Chapter 6 on: lights with a shape are sampled.
    /// Adaptive depth control: a secondary ray whose weight in the pixel would fall below this
    /// is not traced (its light could not change an 8-bit pixel by a whole level). 0 traces
    /// everything up to maxDepth. Source: POV-Ray's adc_bailout, default 1/255.
    double minWeight = 1.0 / 256.0;
};

/// The media of a ray that starts in air: the default of Integrator::trace, one shared constant
/// so a camera ray does not zero a fresh 16-entry stack.
inline constexpr MediumStack kNoMedia{};

class Integrator;
class PixelSampler;
class PostProcess;
class CameraRayGenerator;

/// What a shading routine may use: the scene, the integrator (to trace more rays), this
/// sample's random stream, this thread's counters, the recursion depth and the media the
/// ray travels through.
struct ShadeContext {
    const Scene& scene;
    const Integrator& integrator;
    Sampler& sampler;
    RayCounters& counters;
    int depth;
    const MediumStack& media;
    double weight;  ///< How much this surface's colour counts in the pixel (1 at the camera).
    /// False once the path has counted A4's ambient term at a scattering event (chapter 17):
    /// the ambient light stands for all the indirect light, so a path counts it once.
    bool ambient = true;
};

/// The local shading model: chapter 1 has a headlight; chapter 2 replaces it with Phong.
using SurfaceShader = Colour (*)(const ShadeContext& ctx, const Ray& ray, const Hit& hit);

/// A secondary-ray term (mirror reflection, transmission ...): the extension point chapters
/// 4 and 5 plug into. Terms run in chapter order, each turning the colour so far into a new one.
class ShadingTerm {
  public:
    virtual ~ShadingTerm() = default;
    /// The colour at hit after this term, given the colour so far.
    virtual Colour apply(const ShadeContext& ctx, const Ray& ray, const Hit& hit,
                         const Colour& colour) const = 0;
};

/// Spreads a specular direction into a lobe: chapter 7's glossy reflection and translucency.
/// Reflection and refraction ask it for directions when it is installed.
class LobeSampler {
  public:
    virtual ~LobeSampler() = default;
    /// How many directions to average at a surface of material m (0: keep the sharp one).
    virtual int sampleCount(const Material& m) const = 0;
    /// Draw a direction around the unit specular direction `axis`. Returns false when it falls
    /// on the wrong side of the surface (normal n, pointing to the side the ray must leave
    /// towards); such a sample carries no light.
    virtual bool sample(const Material& m, const Vec3& axis, const Vec3& n, Sampler& sampler,
                        Vec3& direction) const = 0;
};

/// Changes a hit's shading normal (and where its shadow rays start) before it is shaded: the
/// extension point of chapter 9's smooth meshes and chapter 11's bumps, run in chapter order.
/// The geometric normal ng stays as it is.
class ShadingNormal {
  public:
    virtual ~ShadingNormal() = default;
    /// Adjust hit.ns and hit.shadowOffset for the ray that found the hit.
    virtual void apply(const Ray& ray, Hit& hit) const = 0;
};

/// Chapter 10's texture lookup for material colours: the material the surface shader sees at
/// `hit` (kd, ks and shininess with the material's textures evaluated there; no parameters or
/// textures). Called only for a hit whose material has textures.
using TextureLookup = Material (*)(const Hit& hit);

/// What media do to the light along a ray (chapter 17's fog and smoke): the extension point
/// for everything between a ray's origin and the surface it reaches.
class MediaTerm {
  public:
    virtual ~MediaTerm() = default;
    /// The light scattered towards the ray's origin by the media along it up to tEnd (in units
    /// of ray.d; infinity when the ray leaves the scene), and in `throughput` the fraction of
    /// the light from tEnd (the surface or the background) that arrives. A zero throughput
    /// means the surface need not be shaded.
    virtual Colour segment(const ShadeContext& ctx, const Ray& ray, double tEnd,
                           Colour& throughput) const = 0;
    /// The fraction of light that crosses the media from a to b (a shadow ray whose surfaces
    /// were already tested).
    virtual Colour transmittance(const Vec3& a, const Vec3& b, Sampler& sampler,
                                 RayCounters& counters) const = 0;

    /// Where a path scatters in the media along the ray up to tEnd (chapter 18's one path
    /// loop): false when it reaches tEnd (`beta` is multiplied by the free-flight weight, the
    /// transmittance's estimate); true with the particle at x, the phase function's asymmetry
    /// g and `beta` multiplied by the flight's weight (the albedo for a grey medium). An
    /// absorbed path returns true with beta zero.
    struct Interaction {
        Vec3 x{0.0};     ///< Where the particle is.
        double g = 0.0;  ///< Its Henyey–Greenstein asymmetry.
    };
    virtual bool sampleInteraction(const ShadeContext& ctx, const Ray& ray, double tEnd,
                                   Colour& beta, Interaction& interaction) const = 0;
    /// The phase function's value for light travelling along unit `travel` and leaving along
    /// unit `out` (per steradian), and a direction drawn from it (its pdf equals its value).
    virtual double phase(double g, const Vec3& travel, const Vec3& out) const = 0;
    virtual Vec3 samplePhase(double g, const Vec3& travel, const Vec2& u) const = 0;
};

/// Radiance along a camera ray by a method of its own, replacing the surface shader and the
/// secondary terms (chapter 18's path tracer).
class RadianceEstimator {
  public:
    virtual ~RadianceEstimator() = default;
    /// The radiance arriving along the ray (reversed).
    virtual Colour Li(const Integrator& integrator, const Ray& ray, Sampler& sampler,
                      RayCounters& counters) const = 0;
};

/// How a render is put together; each enabled feature adjusts it.
struct Pipeline {
    SurfaceShader surface = nullptr;                        ///< Local shading (chapter 1, then 2).
    AggregateBuilder buildAggregate = nullptr;              ///< Acceleration (chapter 1, then 3).
    std::vector<std::shared_ptr<const ShadingTerm>> terms;  ///< Secondary terms, in order.
    std::shared_ptr<const LobeSampler> lobe;                ///< Glossy lobes (chapter 7), or null.
    /// Shading-normal changes, in chapter order (chapter 9's smooth meshes, then chapter 11's
    /// bumps); empty by default.
    std::vector<std::shared_ptr<const ShadingNormal>> normals;
    /// Where a pixel's camera rays go (chapter 8's supersampling), or null: the core's one
    /// ray through each pixel centre (or --spp random positions).
    std::shared_ptr<const PixelSampler> pixelSampler;
    /// Textured material colours (chapter 10), or null: the materials' own colours.
    TextureLookup textureLookup = nullptr;
    /// What happens to the film after the render (chapter 12's tone map), or null: the film is
    /// written as it is, each channel clamped to [0, 1] as the CS488 framework does.
    std::shared_ptr<const PostProcess> postProcess;
    /// How an image position becomes a camera ray (chapter 13's thin lens), or null: the
    /// pinhole camera's ray.
    std::shared_ptr<const CameraRayGenerator> cameraRays;
    /// Work before the first camera ray (chapter 16's photon tracing), in chapter order;
    /// empty by default.
    std::vector<std::shared_ptr<PrePass>> prePasses;
    /// Participating media along every ray (chapter 17), or null: rays cross empty space.
    std::shared_ptr<const MediaTerm> media;
    /// A method that computes a camera ray's radiance itself (chapter 18's path tracer), or
    /// null: Whitted's recursion through the surface shader and the terms above.
    std::shared_ptr<const RadianceEstimator> radiance;
};

/// Traces rays through a scene with a pipeline.
class Integrator {
  public:
    Integrator(const Scene& scene, const Pipeline& pipeline) : scene_(scene), pipeline_(pipeline) {}
    /// Radiance arriving along a ray (reversed): the shaded colour of the first surface, or
    /// the background.
    /// `ambient` is false on a path that has already counted A4's ambient term.
    Colour trace(const Ray& ray, Sampler& sampler, RayCounters& counters, int depth,
                 const MediumStack& media = kNoMedia, double weight = 1.0,
                 bool ambient = true) const;
    /// True when something lies along the ray with t in (0, tMax): the shadow query.
    bool occluded(const Ray& ray, double tMax, RayCounters& counters) const {
        counters.add(RayKind::Shadow);
        return scene_.aggregate->occluded(ray, tMax);
    }
    /// The fraction of light the media let through from a to b: 1 without media (chapter 17).
    Colour transmittance(const Vec3& a, const Vec3& b, Sampler& sampler,
                         RayCounters& counters) const {
        return pipeline_.media ? pipeline_.media->transmittance(a, b, sampler, counters)
                               : Colour(1.0);
    }
    /// True when media fill some of the scene (chapter 17).
    bool hasMedia() const { return pipeline_.media != nullptr; }
    /// The scene this integrator traces.
    const Scene& scene() const { return scene_; }
    /// The colour of the surface at hit, seen along ray: local shading, then each chapter's
    /// secondary term (smooth normals and bumps adjust hit first).
    Colour shade(const ShadeContext& ctx, const Ray& ray, Hit& hit) const;
    /// The pipeline this integrator runs.
    const Pipeline& pipeline() const { return pipeline_; }

  private:
    const Scene& scene_;
    const Pipeline& pipeline_;
};

/// Chapter 1's shading: the eye is a light (kd · |n·v|), so shapes read as solid.
Colour shadeHeadlight(const ShadeContext& ctx, const Ray& ray, const Hit& hit);

}  // namespace rb
