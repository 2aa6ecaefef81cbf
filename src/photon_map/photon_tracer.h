/// \file
/// The photon tracer: photons leave every light in proportion to its power and scatter
/// through the scene exactly as the enabled chapters shade it (mirrors, glass, glossy lobes,
/// diffuse bounces), and are stored where they land on diffuse surfaces.
#pragma once

#include <cstdint>
#include <vector>

#include "core/integrator.h"
#include "photon_map/photon.h"

namespace rb {

class Cluster;
class RefractionTerm;

/// Which photons a map keeps, by the path that brought them (Heckbert's notation: L the
/// light, S a specular bounce (mirror, glass, glossy lobe), D a diffuse one).
enum class PhotonPaths {
    Caustic,   ///< L S+ D: focused by mirrors and glass; emitted towards specular objects only.
    Indirect,  ///< L (S|D)* D D: after at least one diffuse bounce (colour bleeding).
    Direct,    ///< L D: the first hit only. Shadow rays draw this light; for tests.
};

/// What surfaces do to photons: the chapters of the render that scatter them.
struct PhotonScattering {
    bool mirrors = false;                        ///< Chapter 4 is on: "reflect" bounces.
    const RefractionTerm* refraction = nullptr;  ///< Chapter 5's term, when on: glass.
    const LobeSampler* lobe = nullptr;           ///< Chapter 7's lobes, when on.
    const Pipeline* pipeline = nullptr;          ///< For shading normals (chapters 9, 11).

    /// What the enabled chapters of `pipeline` do to photons.
    static PhotonScattering of(const Pipeline& pipeline);
    /// True when material m sends photons on specularly (a mirror or glass here).
    bool specular(const Material& m) const;
    /// The share of the photons arriving at m that go on specularly (0 when none do).
    double specularShare(const Material& m) const;
    /// The same for caustic paths: 0 where the material says `caustics = false` (a faint,
    /// broad mirror such as a polished floor, whose caustic is a dim glow, not a focus).
    double causticShare(const Material& m) const;
    /// Spread a specular direction into chapter 7's lobe, when the material is glossy there.
    /// Returns false when the lobe's sample falls below the surface (side: the normal of the
    /// side the direction must leave towards): the particle is absorbed.
    bool spread(const Material& m, const Vec3& side, Sampler& sampler, Vec3& direction) const;
};

/// One pass of one map.
struct PhotonTraceSettings {
    PhotonPaths paths = PhotonPaths::Caustic;
    std::uint64_t photons = 0;  ///< Photons emitted (each map's flux is divided by this).
    int pass = 0;               ///< Which pass: each draws its own random streams.
    std::uint64_t seed = 0;     ///< --seed.
    /// Emission directions stratified over photon index (the first ⌊√N⌋² photons each take
    /// one cell of a grid over the direction square); false: independent.
    bool stratify = true;
    /// The processes sharing the pass (MPI ranks): each traces a contiguous share of the
    /// chunks, joined in process order. Null: this process traces every photon.
    Cluster* cluster = nullptr;
};

/// The most photons one emitted photon leaves in a map: its path ends at its 16th stored
/// photon. Charging the memory budget needs this bound; the light it drops is at most
/// ρ^16 of what the path carried (3% for albedo 0.8).
inline constexpr int kMaxStoredPerPhoton = 16;
/// The most bounces a photon path takes (Russian roulette normally ends it much sooner).
inline constexpr int kMaxPhotonBounces = 64;

/// Trace one pass: emit `settings.photons` photons and return those the map keeps, in photon
/// order (the same for any thread count). Rays are counted as RayKind::Photon.
std::vector<Photon> tracePhotons(const Scene& scene, const PhotonScattering& scattering,
                                 const PhotonTraceSettings& settings, RayCounters& counters);

/// Trace several passes, of one map or of several, as one parallel loop over all their chunks
/// (one pass alone has too few to keep every thread busy to its end). Entry j of the result is
/// what tracePhotons(passes[j]) returns.
std::vector<std::vector<Photon>> tracePhotonPasses(const Scene& scene,
                                                   const PhotonScattering& scattering,
                                                   const std::vector<PhotonTraceSettings>& passes,
                                                   RayCounters& counters);

}  // namespace rb
