/// \file
/// Chapter 16's samplers in the sampling lab: the directions in which lights emit photons
/// (emission.h): uniform over the sphere (point lights), cosine-weighted over a hemisphere
/// (area lights) and uniform in a cone (photons aimed at a caustic target), each compared
/// with the pdf beside it.
#include "lab/warp.h"
#include "photon_map/emission.h"

namespace rb {

namespace {

/// An axis along no coordinate axis, so the samplers' frames are exercised.
const Vec3 kEmissionAxis = glm::normalize(Vec3(-0.4, 0.2, 0.9));

/// Draw `count` directions from `sample(u1, u2)`, with random streams (seed, stream, i), in the
/// lab's coordinates about `axis`.
template <typename Sample>
void drawDirections(std::uint64_t count, std::uint64_t seed, std::uint64_t stream, const Vec3& axis,
                    std::vector<Vec2>& points, Sample sample) {
    drawEach(count, seed, stream, points, [&](Sampler& sampler) {
        const Vec2 u = sampler.next2D();
        return directionCoordinates(sample(u.x, u.y), axis);
    });
}

Warp sphereWarp() {
    Warp w;
    w.name = "photon-sphere";
    w.chapter = 16;
    w.title = "a point light's photons: uniform over the sphere, pdf 1/(4π)";
    w.setup = [](const std::map<std::string, double>&) {
        WarpSetup s;
        s.domain = directionDomain(-1.0);
        s.caption = "directions about the z axis";
        s.draw = [](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawDirections(count, seed, 160, Vec3(0.0, 0.0, 1.0), points,
                           [](double u1, double u2) { return sampleUniformSphere(u1, u2); });
        };
        s.pdf = [](const Vec2&) { return uniformSpherePdf(); };
        return s;
    };
    return w;
}

Warp cosineWarp() {
    Warp w;
    w.name = "photon-cosine";
    w.chapter = 16;
    w.title = "an area light's photons: cosine-weighted over its hemisphere, pdf cos θ / π";
    w.setup = [](const std::map<std::string, double>&) {
        WarpSetup s;
        s.domain = directionDomain(0.0);
        s.caption = "directions about a skew normal";
        s.draw = [](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawDirections(count, seed, 161, kEmissionAxis, points, [](double u1, double u2) {
                return sampleCosineHemisphere(kEmissionAxis, u1, u2);
            });
        };
        s.pdf = [](const Vec2& q) { return cosineHemispherePdf(q.y); };
        return s;
    };
    return w;
}

Warp coneWarp() {
    Warp w;
    w.name = "photon-cone";
    w.chapter = 16;
    w.title = "photons aimed at a caustic target: uniform in a cone, pdf 1/(2π(1 − cos θ_max))";
    w.parameters = {{"angle", 20.0, 0.01, 180.0, "the cone's half-angle θ_max, in degrees"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const double cosThetaMax = std::cos(v.at("angle") * M_PI / 180.0);
        WarpSetup s;
        s.domain = directionDomain(cosThetaMax);
        s.caption = "half-angle " + warpNumber(v.at("angle")) + "°";
        s.draw = [cosThetaMax](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawDirections(count, seed, 162, kEmissionAxis, points, [&](double u1, double u2) {
                return sampleUniformCone(kEmissionAxis, cosThetaMax, u1, u2);
            });
        };
        s.pdf = [cosThetaMax](const Vec2& q) {
            return q.y >= cosThetaMax ? 1.0 / coneSolidAngle(cosThetaMax) : 0.0;
        };
        return s;
    };
    return w;
}

}  // namespace

/// Chapter 16's samplers for ./rt --warptest.
std::vector<Warp> photonEmissionWarps() {
    return {sphereWarp(), cosineWarp(), coneWarp()};
}

}  // namespace rb
