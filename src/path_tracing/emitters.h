/// \file
/// Emitting surfaces as lights (chapter 18): every instance whose material emits, with a way
/// to pick a point on it and the density of that choice, for next-event estimation and MIS.
#pragma once

#include <unordered_map>
#include <vector>

#include "core/instance.h"

namespace rb {

/// A point drawn on an emitting surface, seen from a shading point.
struct EmitterSample {
    Vec3 p{0.0};         ///< The point on the emitter.
    Vec3 n{0.0};         ///< The emitter's unit normal there (its emitting side).
    Colour Le{0.0};      ///< Its emitted radiance.
    double pdfArea = 0;  ///< The density of the choice per unit area (emitter choice included).
};

/// The emitting instances of a scene. Boxes and meshes (flat triangles under any affine
/// transform) and spheres under a uniform scale are sampled by area; any other emitting shape
/// is found by the paths' own bounces alone (its light pdf is 0, and MIS gives it weight 1).
class Emitters {
  public:
    /// Gather the emitters among `instances` (their addresses must stay put while this lives).
    explicit Emitters(const std::vector<Instance>& instances);
    /// True when some emitter can be sampled.
    bool sampleable() const { return !cdf_.empty(); }
    /// Pick an emitter by its power, then a point uniformly by area on it.
    EmitterSample sample(double u, const Vec2& uv) const;
    /// The density per unit area with which sample() picks point p of `instance`
    /// (0 for an instance that is not sampled).
    double pdfArea(const Instance* instance) const;

  private:
    /// A flat triangle in world space with its unit normal.
    struct Triangle {
        Vec3 a, e1, e2, n;
    };
    struct Emitter {
        const Instance* instance;
        std::vector<Triangle> triangles;  ///< Empty for a sphere.
        std::vector<double> areaCdf;      ///< Running areas of the triangles.
        Vec3 centre{0.0};                 ///< A sphere's centre ...
        double radius = 0.0;              ///< ... and radius.
        double area = 0.0;
    };
    std::vector<Emitter> emitters_;
    std::vector<double> cdf_;  ///< Running powers (area × mean Le), normalised to end at 1.
    std::unordered_map<const Instance*, int> index_;
};

}  // namespace rb
