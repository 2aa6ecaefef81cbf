/// \file
/// Chapter 6's samplers in the sampling lab: the rectangle light (exercise 6.1) and the cone of
/// a ball light (exercise 6.2), run through RectangleLight::samplePoint and
/// BallLight::samplePoint themselves and compared with pdfArea() and pdfSolidAngle().
#include "core/error.h"
#include "core/sampler.h"
#include "lab/warp.h"
#include "soft_shadows/area_light.h"

namespace rb {

namespace {

/// Draw a light's points as the renderer does: group g of n × n shadow rays takes point k from
/// stream (seed, stream + g, k), with the light's own strategy.
template <typename Visit>
void drawLightPoints(int n, std::uint64_t count, std::uint64_t seed, std::uint64_t stream,
                     Visit visit) {
    const std::uint64_t perGroup = static_cast<std::uint64_t>(n) * n;
    for (std::uint64_t g = 0; g * perGroup < count; ++g)
        for (int k = 0; k < n * n; ++k) {
            Sampler sampler(seed, stream + g, k);
            visit(k, sampler.next2D());
        }
}

Warp rectangleWarp() {
    Warp w;
    w.name = "rectangle";
    w.chapter = 6;
    w.title = "a point on a rectangular light, uniform over its area: pdf_A = 1 / (length · width)";
    w.exercise = "6.1";
    w.parameters = {{"length", 2.0, 1e-3, 1e3, "the side along `left`"},
                    {"width", 1.0, 1e-3, 1e3, "the other side"},
                    {"n", 4, 1, 64, "samples per axis (n × n shadow rays)"},
                    {"stratified", 1, 0, 1, "1: one jittered point per cell; 0: independent"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const double length = v.at("length"), width = v.at("width");
        const int n = static_cast<int>(v.at("n"));
        const Vec3 normal(0.0, -1.0, 0.0), left(1.0, 0.0, 0.0);
        const auto light = std::make_shared<RectangleLight>(
            length, width, normal, left, n,
            v.at("stratified") != 0.0 ? LightSampling::Stratified : LightSampling::Independent);
        WarpSetup s;
        s.domain = {-0.5 * length, 0.5 * length,          -0.5 * width,
                    0.5 * width,   "along left (length)", "along normal × left (width)"};
        s.caption = "length " + warpNumber(length) + ", width " + warpNumber(width) + ", " +
                    std::to_string(n) + " × " + std::to_string(n) +
                    (v.at("stratified") != 0.0 ? " stratified" : " independent");
        s.draw = [light, n](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            // The light hangs at (0, 3, 0) facing down onto a point beside the origin.
            const Vec3 centre(0.0, 3.0, 0.0), p(0.4, 0.0, 0.3);
            const Vec3 up = glm::cross(light->normal(), light->left());
            drawLightPoints(n, count, seed, 6u << 24, [&](int k, const Vec2& u) {
                double weight = 0.0;
                const Vec3 x = light->samplePoint(centre, p, k, n, u, weight) - centre;
                points.push_back({glm::dot(x, light->left()), glm::dot(x, up)});
            });
        };
        s.pdf = [light](const Vec2&) { return light->pdfArea(); };
        return s;
    };
    return w;
}

Warp ballWarp() {
    Warp w;
    w.name = "ball-cone";
    w.chapter = 6;
    w.title =
        "the direction to a point of a ball light, uniform in the cone it fills: "
        "pdf_ω = 1 / (2π(1 − cos θ_max))";
    w.exercise = "6.2";
    w.parameters = {{"radius", 1.0, 1e-3, 1e3, "the ball's radius R"},
                    {"distance", 3.0, 1e-3, 1e6, "from the shading point to the centre (> R)"},
                    {"n", 4, 1, 64, "samples per axis (n × n shadow rays)"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const double radius = v.at("radius"), distance = v.at("distance");
        if (!(distance > radius))
            throw InputError(
                "--warptest ball-cone: distance must exceed radius (the cone is "
                "sampled from outside the ball)");
        const int n = static_cast<int>(v.at("n"));
        const auto light = std::make_shared<BallLight>(radius, n);
        const Vec3 p(0.0), axis = glm::normalize(Vec3(0.3, 0.8, -0.5));
        const Vec3 centre = p + distance * axis;
        // cos θ_max = √(1 − (R/d)²): the cone's edge, the domain's bottom.
        const double cosThetaMax = std::sqrt(1.0 - (radius / distance) * (radius / distance));
        WarpSetup s;
        s.domain = directionDomain(cosThetaMax);
        s.caption = "radius " + warpNumber(radius) + " seen from " + warpNumber(distance) +
                    " away (cos θ_max = " + warpNumber(cosThetaMax) + "), " + std::to_string(n) +
                    " × " + std::to_string(n) + " stratified";
        s.draw = [light, n, p, centre, axis](std::uint64_t count, std::uint64_t seed,
                                             std::vector<Vec2>& points) {
            drawLightPoints(n, count, seed, 7u << 24, [&](int k, const Vec2& u) {
                double weight = 0.0;
                const Vec3 x = light->samplePoint(centre, p, k, n, u, weight);
                points.push_back(directionCoordinates(glm::normalize(x - p), axis));
            });
        };
        s.pdf = [light, p, centre, cosThetaMax](const Vec2& q) {
            return q.y >= cosThetaMax ? light->pdfSolidAngle(centre, p) : 0.0;
        };
        return s;
    };
    return w;
}

}  // namespace

/// Chapter 6's samplers for ./rt --warptest.
std::vector<Warp> softShadowsWarps() {
    return {rectangleWarp(), ballWarp()};
}

}  // namespace rb
