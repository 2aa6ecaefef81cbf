/// \file
/// Chapter 18's path tracer: the rendering equation solved without bias. One loop follows a
/// path through surfaces and media; at each vertex it samples the lights (next-event
/// estimation) and the BSDF or phase function, and weighs the two by multiple importance
/// sampling (the power heuristic). Russian roulette ends paths that carry little light.
#pragma once

#include <memory>
#include <string>

#include "core/integrator.h"
#include "core/pre_pass.h"
#include "path_tracing/emitters.h"

namespace rb {

class RefractionTerm;

/// Which estimators of direct light from emitting surfaces a render combines.
enum class PathStrategy {
    Mis,    ///< Light sampling and BSDF sampling, weighted by the power heuristic (the default).
    Light,  ///< Light sampling alone (next-event estimation).
    Bsdf    ///< BSDF sampling alone: emitters count only when a path happens to hit them.
};

/// How a path-traced render runs: the command line's and the scene's settings.
struct PathSettings {
    int maxDepth = 64;      ///< Bounces at most (a path of maxDepth segments ends there).
    int rouletteDepth = 3;  ///< The bounce from which Russian roulette plays.
    PathStrategy strategy = PathStrategy::Mis;
};

/// The power heuristic's weight of a sample drawn with density pdfA, when another technique
/// could have drawn it with density pdfB: pdfA² / (pdfA² + pdfB²).
/// Source: E. Veach, "Robust Monte Carlo Methods for Light Transport Simulation", 1997, §9.2.
double powerHeuristic(double pdfA, double pdfB);

/// The path tracer: a RadianceEstimator for camera rays, and a PrePass that gathers the
/// emitting surfaces once the scene's instances are final.
class PathTracer final : public RadianceEstimator, public PrePass {
  public:
    explicit PathTracer(const PathSettings& settings) : settings_(settings) {}
    Colour Li(const Integrator& integrator, const Ray& ray, Sampler& sampler,
              RayCounters& counters) const override;
    void run(const Scene& scene, const Pipeline& pipeline, const PrePassContext& ctx) override;
    std::string statistics() const override;
    /// The settings this tracer runs with.
    const PathSettings& settings() const { return settings_; }

  private:
    struct Vertex;
    /// Light arriving at a vertex from the scene's point and area lights and one point of
    /// one emitting surface, times the vertex's scattering (BSDF or phase function).
    Colour directLight(const Integrator& integrator, const Vertex& v, Sampler& sampler,
                       RayCounters& counters) const;

    /// Russian roulette after bounce `depth`: false ends the path; a survivor's beta is scaled.
    bool survivesRoulette(int depth, Colour& beta, Sampler& sampler) const;

    PathSettings settings_;
    std::unique_ptr<Emitters> emitters_;
    bool mirrors_ = false;                        ///< Chapter 4 is on.
    const RefractionTerm* refraction_ = nullptr;  ///< Chapter 5's term, when on.
    const LobeSampler* lobe_ = nullptr;           ///< Chapter 7's lobes, when on.
};

}  // namespace rb
