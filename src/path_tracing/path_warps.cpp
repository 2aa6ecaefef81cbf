/// \file
/// Chapter 18's samplers in the sampling lab: the BSDF's own directions (Lambert and the
/// normalized Phong lobe, mixed by their shares) and light sampling in solid angle (a point
/// on an emitting panel, seen from a shading point), each compared with the pdf the path
/// tracer's MIS weights use.
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "core/box.h"
#include "lab/warp.h"
#include "path_tracing/bsdf.h"
#include "path_tracing/emitters.h"

namespace rb {

namespace {

Warp bsdfWarp() {
    Warp w;
    w.name = "path-bsdf";
    w.chapter = 18;
    w.title =
        "the path tracer's BSDF sampling: Lambert and the normalized Phong lobe, pdf "
        "(kd cos θ/π + ks (n+1)/(2π) cos^n α)/(kd + ks)";
    w.exercise = "18.3";
    w.parameters = {{"kd", 0.5, 0.0, 1.0, "the Lambertian share"},
                    {"ks", 0.4, 0.0, 1.0, "the Phong share"},
                    {"exponent", 20.0, 0.0, 10000.0, "the Phong exponent n"},
                    {"angle", 40.0, 0.0, 89.0, "the angle of incidence, in degrees"}};
    w.setup = [](const std::map<std::string, double>& v) {
        auto m = std::make_shared<Material>();
        m->kd = Colour(v.at("kd"));
        m->ks = Colour(v.at("ks"));
        m->shininess = v.at("exponent");
        const double theta = v.at("angle") * M_PI / 180.0;
        const Vec3 wo(std::sin(theta), 0.0, std::cos(theta));
        auto hit = std::make_shared<Hit>();
        hit->ng = hit->ns = Vec3(0.0, 0.0, 1.0);
        auto bsdf = std::make_shared<Bsdf>(*hit, *m, wo, false, nullptr, nullptr);
        WarpSetup s;
        s.domain = directionDomain(0.0);
        s.caption = "kd " + warpNumber(v.at("kd")) + ", ks " + warpNumber(v.at("ks")) +
                    ", n = " + warpNumber(v.at("exponent")) + ", incidence " +
                    warpNumber(v.at("angle")) + "°";
        const Vec3 axis(0.0, 0.0, 1.0);
        // The lambdas keep the material and the hit alive: the BSDF holds references to them.
        s.draw = [bsdf, m, hit, axis](std::uint64_t count, std::uint64_t seed,
                                      std::vector<Vec2>& points) {
            drawEach(count, seed, 180, points, [&](Sampler& sampler) {
                BsdfSample out;
                // A direction below the surface carries no light: it lands outside the domain.
                if (!bsdf->sample(sampler, kNoMedia, out)) return Vec2(std::nan(""));
                return directionCoordinates(out.wi, axis);
            });
        };
        s.pdf = [bsdf, m, hit, axis](const Vec2& q) {
            return bsdf->pdf(directionFromCoordinates(q, axis));
        };
        return s;
    };
    return w;
}

Warp lightWarp() {
    Warp w;
    w.name = "path-light";
    w.chapter = 18;
    w.title =
        "light sampling in solid angle: a uniform point on an emitting panel, pdf "
        "d²/(A cos θ_light)";
    w.exercise = "18.4";
    w.parameters = {{"height", 1.0, 0.05, 100.0, "the panel's height above the shading point"},
                    {"offset", 0.5, 0.0, 10.0, "the panel's sideways offset"}};
    w.setup = [](const std::map<std::string, double>& v) {
        // A thin emitting box, 1.3 × 0.02 × 1.05 (the Cornell box's lamp), above the origin.
        auto box = std::make_shared<Box>();
        auto lamp = std::make_shared<Material>();
        lamp->emission = Colour(1.0);
        auto instances = std::make_shared<std::vector<Instance>>(1);
        Instance& panel = (*instances)[0];
        panel.shape = box.get();
        panel.material = lamp.get();
        const Vec3 corner(v.at("offset") - 0.65, v.at("height"), -0.525);
        panel.setTransform(glm::translate(Mat4(1.0), corner) *
                           glm::scale(Mat4(1.0), Vec3(1.3, 0.02, 1.05)));
        auto emitters = std::make_shared<Emitters>(*instances);
        const Vec3 axis = glm::normalize(corner + Vec3(0.65, 0.0, 0.525));
        // Every direction to the panel lies within the cone through its farthest corner.
        double cosMax = 1.0;
        for (int k = 0; k < 8; ++k) {
            const Vec3 c = corner + Vec3(k & 1 ? 1.3 : 0.0, k & 2 ? 0.02 : 0.0, k & 4 ? 1.05 : 0.0);
            cosMax = std::min(cosMax, glm::dot(glm::normalize(c), axis));
        }
        WarpSetup s;
        s.domain = directionDomain(std::max(-1.0, cosMax - 1e-3));
        s.caption = "a 1.3 × 1.05 panel at height " + warpNumber(v.at("height")) + ", offset " +
                    warpNumber(v.at("offset"));
        // The lambdas keep the box and the lamp's material alive: the instance points at them.
        s.draw = [emitters, instances, box, lamp, axis](std::uint64_t count, std::uint64_t seed,
                                                        std::vector<Vec2>& points) {
            drawEach(count, seed, 181, points, [&](Sampler& sampler) {
                const double u = sampler.next1D();
                const EmitterSample e = emitters->sample(u, sampler.next2D());
                const Vec3 wi = glm::normalize(e.p);
                // The far faces are not seen from the origin: no light comes from them.
                if (glm::dot(e.n, wi) >= 0.0) return Vec2(std::nan(""));
                return directionCoordinates(wi, axis);
            });
        };
        s.pdf = [emitters, instances, box, lamp, axis](const Vec2& q) {
            // The direction back from the lab's coordinates, then the panel's face it meets.
            const Vec3 wi = directionFromCoordinates(q, axis);
            ObjectHit oh;
            const Instance& p = (*instances)[0];
            if (!p.intersect(Ray{Vec3(0.0), wi}, std::numeric_limits<double>::infinity(), oh))
                return 0.0;
            const Vec3 n = glm::normalize(p.normalToWorld * oh.n);
            const double cosLight = -glm::dot(n, wi);
            return cosLight > 0.0 ? emitters->pdfArea(&p) * oh.t * oh.t / cosLight : 0.0;
        };
        return s;
    };
    return w;
}

}  // namespace

std::vector<Warp> pathTracingWarps() {
    return {bsdfWarp(), lightWarp()};
}

}  // namespace rb
