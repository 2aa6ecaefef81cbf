/// \file
/// Chapter 17's sampler in the sampling lab: the Henyey–Greenstein phase function, drawn by
/// sampleHenyeyGreenstein and compared with henyeyGreenstein (exercise 17.1 writes the pdf:
/// a wrong pdf shows as clearly as a wrong sampler), and equiangular points along a ray
/// (exercise 17.4), binned against their distance with a uniform second coordinate.
#include "lab/warp.h"
#include "media/equiangular.h"
#include "media/henyey_greenstein.h"

namespace rb {

namespace {

Warp phaseWarp() {
    Warp w;
    w.name = "hg-phase";
    w.chapter = 17;
    w.title =
        "the Henyey–Greenstein phase function: p(cos θ) = (1 − g²) / (4π (1 + g² − "
        "2g cos θ)^(3/2))";
    w.exercise = "17.1";
    w.parameters = {{"g", 0.5, -0.99, 0.99, "the mean cosine: < 0 back, > 0 forward scattering"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const double g = v.at("g");
        const Vec3 forward = glm::normalize(Vec3(0.6, 0.0, -0.8));
        WarpSetup s;
        s.domain = directionDomain(-1.0);
        s.caption = "g = " + warpNumber(g) + ", about the direction of travel";
        s.draw = [g, forward](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawEach(count, seed, 170, points, [g, forward](Sampler& sampler) {
                return directionCoordinates(sampleHenyeyGreenstein(forward, g, sampler.next2D()),
                                            forward);
            });
        };
        s.pdf = [g](const Vec2& q) { return henyeyGreenstein(q.y, g); };
        return s;
    };
    return w;
}

Warp equiangularWarp() {
    Warp w;
    w.name = "equiangular";
    w.chapter = 17;
    w.title =
        "equiangular points on a ray's stretch [0, length]: p(s) = h / (θ_ab (h² + (s − Δ)²)), "
        "for a light h off the ray above s = Δ";
    w.exercise = "17.4";
    w.parameters = {{"h", 0.25, 1e-3, 100.0, "the light's distance from the ray's line"},
                    {"delta", 1.0, -100.0, 100.0, "where along the ray the light is nearest"},
                    {"length", 4.0, 1e-3, 100.0, "the stretch's length"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const EquiangularSegment seg{0.0, v.at("length"), v.at("delta"), v.at("h")};
        WarpSetup s;
        // The second coordinate is a uniform number of the lab's own: the sampler is 1-D.
        s.domain = {seg.a, seg.b, 0.0, 1.0, "distance s along the ray", "uniform u (unused)"};
        s.caption = "h = " + warpNumber(seg.h) + ", Δ = " + warpNumber(seg.delta) + ", length " +
                    warpNumber(seg.b);
        s.draw = [seg](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawEach(count, seed, 171, points, [seg](Sampler& sampler) {
                const double s = sampleEquiangular(seg, sampler.next1D()).s;
                return Vec2(s, sampler.next1D());
            });
        };
        s.pdf = [seg](const Vec2& q) { return equiangularPdf(seg, q.x); };
        return s;
    };
    return w;
}

}  // namespace

/// Chapter 17's samplers for ./rt --warptest.
std::vector<Warp> mediaWarps() {
    return {phaseWarp(), equiangularWarp()};
}

}  // namespace rb
