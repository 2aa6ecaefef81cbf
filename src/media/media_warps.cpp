/// \file
/// Chapter 17's sampler in the sampling lab: the Henyey–Greenstein phase function, drawn by
/// sampleHenyeyGreenstein and compared with henyeyGreenstein (exercise 17.1 writes the pdf:
/// a wrong pdf shows as clearly as a wrong sampler).
#include "lab/warp.h"
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

}  // namespace

/// Chapter 17's samplers for ./rt --warptest.
std::vector<Warp> mediaWarps() {
    return {phaseWarp()};
}

}  // namespace rb
