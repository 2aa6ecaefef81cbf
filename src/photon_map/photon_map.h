/// \file
/// Chapter 16, photon mapping: caustics under glass and mirrors, and indirect diffuse light,
/// from photons traced from the lights before the render (Jensen's two passes), made to
/// converge by shrinking the gather radius from pass to pass (progressive photon mapping).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/feature.h"
#include "core/integrator.h"
#include "core/pre_pass.h"
#include "photon_map/photon_grid.h"
#include "photon_map/photon_tracer.h"

namespace rb {

struct RenderContext;

/// Final gather rays per visible point when the scene does not say (see ch16-gather).
inline constexpr int kDefaultGatherRays = 32;

/// What a render asks of the photon maps: gr.photons{...}, then --photons and friends.
struct PhotonSettings {
    bool on = false;                ///< The scene called gr.photons, or --photons was given.
    std::uint64_t photons = 20000;  ///< Photons emitted per pass, for each map.
    int passes = 16;           ///< Passes; each traces new photons and gathers with its radius.
    double radius = 0.0;       ///< The first pass's gather radius; 0: from the pixel footprint.
    double alpha = 2.0 / 3.0;  ///< The radius shrinks as r²_{i+1} = r²_i (i + α)/(i + 1).
    bool classic = false;      ///< Jensen's classic method: one radius for every pass.
    int nearest = 0;           ///< k > 0: only the k nearest photons within each radius.
    /// m > 0: where fewer than m photons lie within the radius, the disk grows to hold m
    /// (PhotonGrid::gatherAtLeast), so sparse light is not drawn as speckle.
    int atLeast = 0;
    bool caustics = true;      ///< Keep a caustic map (L S+ D).
    bool indirect = false;     ///< Keep an indirect map (L (S|D)* D D); drops the ambient term.
    /// Final gather rays at each visible diffuse point for the indirect light; 0: read the
    /// indirect map there directly.
    int gather = kDefaultGatherRays;
};

/// The settings of one render: the scene's gr.photons, overridden by the command line.
/// Throws InputError for a value out of range, naming the option.
PhotonSettings photonSettings(const RenderContext& context);

/// The gather radius of each pass: r0 for every pass in the classic method; in the
/// progressive one r²_{i+1} = r²_i (i + α)/(i + 1), counting passes from 1.
std::vector<double> passRadii(double r0, double alpha, int passes, bool classic);

/// The density estimate: the irradiance that photons of total flux Φ within radius r stand
/// for, E = Φ / (π r²).
Colour irradianceEstimate(const Colour& flux, double radius);

/// The photons of every pass of one map, and the radius each pass gathers with.
struct PhotonPasses {
    std::vector<PhotonGrid> grids;
    std::vector<double> radii;
    std::uint64_t stored = 0;  ///< Photons in all passes.
    int atLeast = 0;           ///< The gathers' floor of photons (PhotonSettings::atLeast).
    /// With a floor: each pass's photons again, in a grid kWidestGrowth times as wide, where
    /// a gather that found too few grows.
    std::vector<PhotonGrid> wide;
    /// The irradiance at x on the side the unit normal n faces: the mean over the passes of
    /// each pass's estimate (k nearest: within the radius of the k-th).
    Colour irradiance(const Vec3& x, const Vec3& n, int nearest) const;
    /// The same from one pass alone: an unbiased estimate of irradiance() when the pass is
    /// drawn uniformly. Zero for a map with no passes.
    Colour passIrradiance(const Vec3& x, const Vec3& n, int nearest, std::size_t pass) const;
};

/// Chapter 16's shading term and pre-pass: before the render it traces the photons of every
/// pass; during it, each diffuse surface adds kd·E from the maps to what the other chapters
/// shaded (E measured in the units of A4's lights, so a photon map of direct light gives
/// exactly what Phong's diffuse term gives).
class PhotonMapping final : public ShadingTerm, public PrePass {
  public:
    explicit PhotonMapping(const PhotonSettings& settings, std::string where)
        : settings_(settings), where_(std::move(where)) {}
    Colour apply(const ShadeContext& ctx, const Ray& ray, const Hit& hit,
                 const Colour& colour) const override;
    void run(const Scene& scene, const Pipeline& pipeline, const PrePassContext& ctx) override;
    std::string statistics() const override;
    /// The final gather at a visible diffuse point (hit, normal n facing the viewer): the
    /// irradiance of the light that reached it after at least one diffuse bounce, the indirect
    /// map's share, as the mean over `rays` cosine-weighted rays of what each ray sees (see
    /// final_gather.cpp).
    Colour gatherIrradiance(const ShadeContext& ctx, const Hit& hit, const Vec3& n, int rays) const;

    const PhotonPasses& caustics() const { return caustics_; }  ///< The caustic map.
    const PhotonPasses& indirect() const { return indirect_; }  ///< The indirect map.

  private:
    PhotonSettings settings_;
    std::string where_;  ///< The gr.render call, for messages.
    PhotonPasses caustics_, indirect_;
    PhotonScattering scattering_;  ///< What surfaces do to photons, and to gather rays.
    /// The light a final gather ray brings back (π L in A4's units): followed through mirrors
    /// and glass to each diffuse surface, where the direct light counts in full and the maps,
    /// pass `pass`, count (the caustic map once, the indirect map `mapWeight` times, 0: not
    /// read); a ray shorter than the indirect map's radius
    /// times kShortGather continues one diffuse bounce instead of reading the indirect map, at
    /// most `bounces` times.
    Colour gatherRadiance(const ShadeContext& ctx, Ray ray, std::size_t pass, double mapWeight,
                          int bounces) const;
    bool glass_ = false;  ///< Chapter 5 is on: transparent materials are glass, not diffuse.
    double seconds_ = 0.0;
};

/// The bytes one pass of `photons` emitted photons may take at its peak: every photon's
/// stored records (at most kMaxStoredPerPhoton), their copies while the pass is merged and
/// sorted into its grid, and the grid's tables; `wide`: a wide grid's copy and tables too.
std::uint64_t photonPassBytes(std::uint64_t photons, bool wide);

/// Chapter 16's feature record.
Feature photonMapFeature();

}  // namespace rb
