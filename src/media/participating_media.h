/// \file
/// ParticipatingMedia: chapter 17's term in the integrator. It finds which medium fills each
/// stretch of a ray, tracks light through it, and scatters towards the lights.
#pragma once

#include <memory>
#include <vector>

#include "core/instance.h"
#include "core/integrator.h"
#include "media/tracking.h"

namespace rb {

/// How a render treats its media: gr.option values, overridden by the command line.
struct MediaSettings {
    bool march = false;  ///< Ray marching (single scattering only) instead of tracking.
    TransmittanceMethod shadows = TransmittanceMethod::Ratio;  ///< Shadow-ray estimator.
    double step = 0.0;  ///< Marching step in world units; 0: 1/400 of the fog box diagonal.
    int majorantResolution = 16;  ///< Majorant grid cells per axis.
    /// Scatterings a path may take in media after the first (0: single scattering only).
    int bounces = 256;
};

/// The media of one render: the closed shapes that bound media (node:set_medium) and the fog
/// (gr.fog) that fills all space outside them, within the scene's bounds.
class ParticipatingMedia final : public MediaTerm {
  public:
    /// `boundaries` are the instances whose medium is set, in the scene graph's order (a node's
    /// medium nested under another's comes later and wins inside it). `fogBox` is where fog
    /// ends: beyond it rays reach the background.
    ParticipatingMedia(std::vector<Instance> boundaries, const Medium* fog, const AABB& fogBox,
                       const MediaSettings& settings);
    Colour segment(const ShadeContext& ctx, const Ray& ray, double tEnd,
                   Colour& throughput) const override;
    Colour transmittance(const Vec3& a, const Vec3& b, Sampler& sampler,
                         RayCounters& counters) const override;
    bool sampleInteraction(const ShadeContext& ctx, const Ray& ray, double tEnd, Colour& beta,
                           Interaction& interaction) const override;
    double phase(double g, const Vec3& travel, const Vec3& out) const override;
    Vec3 samplePhase(double g, const Vec3& travel, const Vec2& u) const override;

    /// One stretch of a ray inside one medium (or in none: medium == nullptr).
    struct Piece {
        double t0, t1;
        const TrackedMedium* medium;
    };
    /// The stretches of the ray between t = 0 and tEnd, in order; empty space is left out.
    void pieces(const Ray& ray, double tEnd, std::vector<Piece>& out) const;

    /// The light that a particle at x of medium m scatters along the unit direction `travel`
    /// reversed from every light, through attenuated shadow rays (single scattering). A4's
    /// ambient light is the caller's to add, once per path.
    Colour lightScattered(const ShadeContext& ctx, const Vec3& x, const Vec3& travel,
                          const Medium& m) const;

  private:
    /// What a ray meets in the media up to tEnd: nothing (`beta` holds the transmittance),
    /// absorption, or a scattering at x in medium m (`beta` holds the path's weight).
    FreeFlight::Event track(const ShadeContext& ctx, const Ray& ray, double tEnd, Colour& beta,
                            Vec3& x, const Medium*& m) const;
    /// Ray marching through one piece: the single-scattered light it adds, and `tr` dimmed.
    Colour march(const ShadeContext& ctx, const Ray& ray, const Piece& piece, Colour& tr) const;

    std::vector<Instance> boundaries_;
    std::vector<std::unique_ptr<TrackedMedium>> tracked_;  ///< One per boundary, then the fog.
    const TrackedMedium* fog_ = nullptr;
    AABB fogBox_;
    MediaSettings settings_;
};

}  // namespace rb
