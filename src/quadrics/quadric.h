/// \file
/// Quadric: the shape kind of chapter 15. A cylinder or cone is a side surface (a quadric,
/// clipped to the slab −1 ≤ y ≤ 1) and, when capped, the two disks that close it. This header
/// holds what both shapes share: the span of a ray inside a side surface, the slab clip that
/// makes caps and side meet without a gap, and every crossing of a ray's line (for CSG).
#pragma once

#include <array>
#include <cstdint>

#include "core/shape.h"

namespace rb {

/// Which part of a cylinder or cone a crossing lies on (Hit::primitive holds it).
enum class QuadricPart : std::uint32_t {
    Side = 0,    ///< The curved surface.
    Bottom = 1,  ///< The cap at y = −1 (normal −y).
    Top = 2      ///< The cap at y = +1 (normal +y); for a pointed cone, the apex.
};

/// One crossing of a ray's line with a quadric's surface: where, and on which part.
struct QuadricCrossing {
    double t = 0.0;
    QuadricPart part = QuadricPart::Side;
};

/// Where along a ray's whole line a point is inside an infinite side surface: up to two
/// closed intervals [lo, hi], whose ends may be ±∞ (a cone's two nappes give two).
struct SideSpans {
    int count = 0;
    std::array<double, 2> lo{}, hi{};
    /// Add the interval [l, h].
    void add(double l, double h) {
        lo[count] = l;
        hi[count] = h;
        ++count;
    }
};

/// The stretch [tIn, tOut] of a ray's line inside a closed (capped) quadric, and the parts
/// through which the line enters and leaves.
struct SolidSpan {
    double tIn = 0.0, tOut = 0.0;
    QuadricPart partIn = QuadricPart::Side, partOut = QuadricPart::Side;
};

/// Clip the side spans to the slab −1 ≤ y ≤ 1 between the caps; false when nothing is left.
/// Because the solid is the intersection of the two sets, the caps and the side meet with no
/// gap: a line that passes inside near the rim is inside one or the other, never neither.
bool clipToSlab(const Ray& ray, const SideSpans& side, SolidSpan& span);

/// The crossings of a capped shape: the entry and exit of the side spans clipped to the slab
/// (0 or 2).
int solidCrossings(const Ray& ray, const SideSpans& side, std::array<QuadricCrossing, 2>& out);

/// The crossings of an open shape: the finite ends of the side spans that lie between the
/// caps' planes, sorted (0, 1 or 2).
int openCrossings(const Ray& ray, const SideSpans& side, std::array<QuadricCrossing, 2>& out);

/// A cylinder or cone standing on the y axis between y = −1 and y = +1.
class Quadric : public Shape {
  public:
    /// Every crossing of the ray's whole line with the surface (any t, also t ≤ 0), sorted
    /// by t; returns how many there are (0, 1 or 2). A capped shape is a solid and gives 0 or
    /// 2: the line enters at out[0] and leaves at out[1].
    virtual int crossings(const Ray& ray, std::array<QuadricCrossing, 2>& out) const = 0;
    /// The object-space outward normal (any length, never zero) at p on `part`.
    virtual Vec3 normal(const Vec3& p, QuadricPart part) const = 0;
    /// True when the caps close the shape, so it has an inside (refraction, CSG).
    bool capped() const { return capped_; }

    /// Every crossing as an object-space hit (t, outward normal, uv, part as primitive),
    /// sorted by t, t ≤ 0 included; returns how many (0, 1 or 2). This is what CSG needs: a
    /// capped shape gives the interval [out[0].t, out[1].t] where the line is inside it.
    int allHits(const Ray& ray, std::array<ObjectHit, 2>& out) const override;

    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    bool occluded(const Ray& ray, double tMax) const override;
    AABB bounds() const override { return AABB{Vec3(-1.0), Vec3(1.0)}; }
    const char* feature() const override { return "quadrics"; }
    /// quadricUv at p on `part`, with dp/du and dp/dv: textures wrap round the side.
    bool surfaceCoordinates(const Vec3& p, std::uint32_t part, Vec2& uv, Vec3& dpdu,
                            Vec3& dpdv) const override;
    /// dr/dy of the side's radius r(y): 0 for a cylinder.
    virtual double radiusSlope() const { return 0.0; }

  protected:
    explicit Quadric(bool capped) : capped_(capped) {}

  private:
    /// Fill an object-space hit at t on `part`: point, normal, uv and part.
    ObjectHit hitAt(const Ray& ray, const QuadricCrossing& c) const;
    bool capped_;
};

/// Surface coordinates on a cylinder or cone: on the side u = φ/2π with φ = atan2(x, z)
/// (0 facing +z, growing towards +x) and v = (y + 1)/2 up the axis; on a cap the disk seen
/// from above, u = (x + 1)/2, v = (z + 1)/2.
Vec2 quadricUv(const Vec3& p, QuadricPart part);

}  // namespace rb
