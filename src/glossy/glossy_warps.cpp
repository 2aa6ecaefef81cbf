/// \file
/// Chapter 7's samplers in the sampling lab: the importance-sampled Phong lobe (exercise 7.1)
/// and seed 000's fuzz sphere (exercise 7.2), run through samplePhongLobe and sampleFuzzSphere
/// and compared with phongLobePdf and fuzzSpherePdf.
#include <cmath>

#include "glossy/lobe_samplers.h"
#include "lab/warp.h"

namespace rb {

namespace {

/// A lobe axis along no coordinate axis, so the samplers' frames are exercised.
const Vec3 kLobeAxis = glm::normalize(Vec3(0.3, -0.5, 0.8));

Warp phongLobeWarp() {
    Warp w;
    w.name = "phong-lobe";
    w.chapter = 7;
    w.title = "the Phong lobe about the mirror direction: p(ω) = (n+1)/(2π) cos^n α";
    w.exercise = "7.1";
    w.parameters = {{"exponent", 20.0, 0.0, 1e5, "the Phong exponent n"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const double n = v.at("exponent");
        WarpSetup s;
        // cos α from the value below which the lobe holds 0.1% of its directions
        // (P(cos α < μ) = μ^(n+1)), so the bins cover the lobe and not the empty hemisphere;
        // the rest is the outside cell.
        s.domain = directionDomain(std::pow(1e-3, 1.0 / (n + 1.0)));
        s.caption = "exponent n = " + warpNumber(n);
        s.draw = [n](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawEach(count, seed, 70, points, [n](Sampler& sampler) {
                const Vec2 u = sampler.next2D();
                return directionCoordinates(samplePhongLobe(kLobeAxis, n, u.x, u.y), kLobeAxis);
            });
        };
        s.pdf = [n](const Vec2& q) { return phongLobePdf(n, q.y); };
        return s;
    };
    return w;
}

Warp fuzzSphereWarp() {
    Warp w;
    w.name = "fuzz-sphere";
    w.chapter = 7;
    w.title = "the fuzz sphere: normalize(axis + f·b), b uniform in the unit ball";
    w.exercise = "7.2";
    w.parameters = {{"fuzz", 0.5, 1e-3, 10.0, "the radius f of the fuzz ball"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const double f = v.at("fuzz");
        WarpSetup s;
        // Below f = 1 the directions fill the cone sin α ≤ f; from f = 1 every direction.
        s.domain = directionDomain(f < 1.0 ? std::sqrt(1.0 - f * f) : -1.0);
        s.caption = "fuzz f = " + warpNumber(f);
        s.draw = [f](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawEach(count, seed, 71, points, [f](Sampler& sampler) {
                const double u1 = sampler.next1D(), u2 = sampler.next1D(), u3 = sampler.next1D();
                return directionCoordinates(sampleFuzzSphere(kLobeAxis, f, u1, u2, u3), kLobeAxis);
            });
        };
        s.pdf = [f](const Vec2& q) { return fuzzSpherePdf(f, q.y); };
        return s;
    };
    return w;
}

}  // namespace

/// Chapter 7's samplers for ./rt --warptest.
std::vector<Warp> glossyWarps() {
    return {phongLobeWarp(), fuzzSphereWarp()};
}

}  // namespace rb
