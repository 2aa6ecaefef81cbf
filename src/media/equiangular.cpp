#include "media/equiangular.h"

#include <algorithm>
#include <cmath>

namespace rb {

namespace {

/// The angle the stretch [a, b] subtends at the light, in (0, π): θ(b) − θ(a) with
/// θ(s) = atan((s − Δ) / h), written as one atan2 so that it keeps its digits when the light
/// lies far off the stretch's end, where θ(a) and θ(b) are both near ±π/2.
double subtendedAngle(const EquiangularSegment& seg) {
    return std::atan2(seg.h * (seg.b - seg.a),
                      seg.h * seg.h + (seg.a - seg.delta) * (seg.b - seg.delta));
}

}  // namespace

// [equiangular]
EquiangularSample sampleEquiangular(const EquiangularSegment& seg, double u) {
    // [exercise-equiangular]
    // Exercise 17.4, equiangular sampling: read ch17-equiangular.
    // Blank: return {seg.a, 1.0};
    // Step 1: the angle θ is uniform between θ(a) and θ(b).
    const double thetaA = std::atan((seg.a - seg.delta) / seg.h);
    const double theta = thetaA + u * subtendedAngle(seg);
    // Step 2: back to a distance along the ray; rounding may step just past the stretch.
    const double s = std::clamp(seg.delta + seg.h * std::tan(theta), seg.a, seg.b);
    return {s, equiangularPdf(seg, s)};
    // [exercise-equiangular]
}

double equiangularPdf(const EquiangularSegment& seg, double s) {
    const double x = s - seg.delta;
    return seg.h / (subtendedAngle(seg) * (seg.h * seg.h + x * x));
}
// [equiangular]

}  // namespace rb
