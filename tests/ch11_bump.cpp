/// \file
/// Chapter 11 tests: bump mapping.
///
/// Chapter 11 claims that a height field h over a surface, scaled by a strength a, changes the
/// shading normal to that of the displaced surface x + a·h·n, n' = normalize(n − a·∇h) (Blinn
/// 1978), with the surface gradient ∇h taken by central differences; and that the bumped
/// normal never tips over to the side of the surface the viewer cannot see. The tests prove it
/// on height fields whose gradient is known exactly: a planar ramp h = s·x tilts the normal by
/// exactly atan(a·s), in object space and through a non-uniform scale, and a lit floor with a
/// ramp shades as a tilted floor would; ripples have a closed-form gradient, and the numerical
/// one converges to it at the rate central differences promise (error ∝ step²). A zero strength
/// leaves every normal bit for bit; no strength, however large, makes a bumped normal face away
/// from the viewer, although the raw formula does (the stability cases show it does, and that
/// the result stays finite). A scene without bumps, and `--features=all,-bump`, render bit for
/// bit as without the chapter.
#include <stb_image_write.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <memory>
#include <string>
#include <vector>

#include "bump/bump.h"
#include "bump/gradient_noise.h"
#include "bump/height_map.h"
#include "bump/procedural_heights.h"
#include "core/error.h"
#include "test_helpers.h"
#include "texture/texture_image.h"

using Catch::Contains;
using rb::Colour;
using rb::Vec3;

namespace {

/// The chapters 1–11 with everything on (those of them that this tree has).
rb::FeatureSet withBump() {
    return rbtest::chapters(11);
}

/// How many of the pipeline's shading-normal stages are chapter 11's bumps.
size_t bumpStages(const rb::World& world) {
    size_t n = 0;
    for (const auto& stage : world.pipeline.normals)
        if (dynamic_cast<const rb::BumpNormals*>(stage.get())) ++n;
    return n;
}

/// The angle between two unit vectors, computed stably (atan2 of |a × b| and a · b).
double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

/// A material that carries `bump`.
rb::Material bumpedMaterial(std::shared_ptr<const rb::NormalPerturbation> bump) {
    rb::Material m{Colour(0.8), Colour(0.0), 1.0, {}, {}};
    m.bump = std::move(bump);
    return m;
}

/// The world-space hit of `ray` on an instance, or fail the test.
rb::Hit hitOf(const rb::Instance& instance, const rb::Ray& ray) {
    rb::ObjectHit oh;
    REQUIRE(instance.intersect(ray, std::numeric_limits<double>::infinity(), oh));
    return instance.toWorld(ray, oh);
}

/// A height field that returns whatever it is given: NaN, Inf or huge numbers.
class ConstantJunk final : public rb::HeightField {
  public:
    explicit ConstantJunk(double slope) : slope_(slope) {}
    double height(const Vec3& x) const override { return slope_ * x.x; }
    double featureSize() const override { return 1.0; }

  private:
    double slope_;
};

/// Write a 256 × 4 grey PNG whose column x has level x (a ramp of one level per texel) into
/// `dir` and return its path.
std::string writeRampPng(const rbtest::TempDir& dir) {
    std::vector<unsigned char> pixels;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 256; ++x) pixels.push_back(static_cast<unsigned char>(x));
    const std::string path = (dir.path() / "ramp.png").string();
    REQUIRE(stbi_write_png(path.c_str(), 256, 4, 1, pixels.data(), 256) != 0);
    return path;
}

/// Write a 4 × 256 grey PNG whose row y, counted from the top as the file stores it, has level
/// 255 − y (a ramp that rises towards the image's top, +v) into `dir` and return its path.
std::string writeUpwardRampPng(const rbtest::TempDir& dir) {
    std::vector<unsigned char> pixels;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 4; ++x) pixels.push_back(static_cast<unsigned char>(255 - y));
    const std::string path = (dir.path() / "upward-ramp.png").string();
    REQUIRE(stbi_write_png(path.c_str(), 4, 256, 1, pixels.data(), 4) != 0);
    return path;
}

}  // namespace

// [ch11-bumped-normal-alone]
SCENARIO("the bumped normal is n − a·g, normalised, and tends to −g as the strength grows",
         "[ch11][ex11.1]") {
    GIVEN("the normal n = +y and a tangential gradient g = (s, 0, 0)") {
        const Vec3 n(0, 1, 0);
        THEN("strength a tilts it to (−a·s, 1, 0) / √(1 + (a·s)²)") {
            // Source: the chapter's equation n' = (n − a·g) / |n − a·g|.
            for (const double s : {0.1, 1.0, 3.0})
                for (const double a : {0.5, 1.0, -2.0}) {
                    const Vec3 expected = Vec3(-a * s, 1.0, 0.0) / std::sqrt(1.0 + a * a * s * s);
                    const Vec3 bumped = rb::bumpedNormal(n, Vec3(s, 0, 0), a);
                    INFO("s = " << s << ", a = " << a << ": expected the normal (" << expected.x
                                << ", " << expected.y << ", 0), got (" << bumped.x << ", "
                                << bumped.y << ", " << bumped.z << ")");
                    CHECK(glm::length(bumped - expected) < 1e-14);
                }
        }
        THEN("a strength of 1e300 gives the direction of −g, finite, not an overflow") {
            const Vec3 bumped = rb::bumpedNormal(n, Vec3(0.5, 0, 0), 1e300);
            INFO("expected (−1, 0, 0), got (" << bumped.x << ", " << bumped.y << ", " << bumped.z
                                              << ")");
            CHECK(glm::length(bumped - Vec3(-1, 0, 0)) < 1e-12);
        }
        THEN("a zero gradient leaves the normal as it was") {
            CHECK(rb::bumpedNormal(n, Vec3(0.0), 5.0) == n);
        }
    }
}
// [ch11-bumped-normal-alone]

namespace {

/// A plane wave h(x) = sin(k·(x·d)) of wavelength λ along the unit direction d: the test's own
/// height field, with a gradient known in closed form, so that the numerical gradient is
/// checked without exercise 11.4's ripples.
class PlaneWave final : public rb::HeightField {
  public:
    PlaneWave(const Vec3& d, double lambda)
        : d_(glm::normalize(d)), k_(2.0 * glm::pi<double>() / lambda), lambda_(lambda) {}
    double height(const Vec3& x) const override { return std::sin(k_ * glm::dot(x, d_)); }
    double featureSize() const override { return lambda_; }
    /// Source: ∇ sin(k·(x·d)) = k·cos(k·(x·d))·d.
    Vec3 exactGradient(const Vec3& x) const { return k_ * std::cos(k_ * glm::dot(x, d_)) * d_; }
    double k() const { return k_; }

  private:
    Vec3 d_;
    double k_, lambda_;
};

}  // namespace

SCENARIO("the numerical gradient of a plane wave converges to its slope as the step squared",
         "[ch11][ex11.2]") {
    GIVEN("a plane wave of wavelength 0.2 across a tilted direction, 100 points on y = 0.5") {
        const PlaneWave wave(Vec3(1.0, 0.5, 2.0), 0.2);
        rbtest::Rng rng(11);
        std::vector<Vec3> points;
        for (int i = 0; i < 100; ++i)
            points.emplace_back(rng.uniform(-1, 1), 0.5, rng.uniform(-1, 1));
        const Vec3 n(0, 1, 0);
        // The largest error of the numerical gradient against the exact one's part along the
        // surface (the tangent plane of n), at one step.
        const auto worstError = [&](double step) {
            double worst = 0.0;
            for (const Vec3& x : points) {
                const Vec3 exact = wave.exactGradient(x);
                const Vec3 tangential = exact - glm::dot(exact, n) * n;
                worst = std::max(worst,
                                 glm::length(rb::surfaceGradient(wave, x, n, step) - tangential));
            }
            return worst;
        };
        WHEN("the step halves from λ/20 to λ/40") {
            const double coarse = worstError(0.2 / 20), fine = worstError(0.2 / 40);
            THEN("the error falls by about 4") {
                // Source: Taylor's theorem: (h(x+ε) − h(x−ε)) / 2ε = h'(x) + ε² h'''(x) / 6 +
                // O(ε⁴), so halving ε quarters the leading error.
                INFO("expected central differences, whose error falls 4-fold as the step halves: "
                     << coarse << " to " << fine);
                CHECK(coarse / fine == Approx(4.0).epsilon(0.05));
            }
        }
        WHEN("the default step, λ/1000, is used") {
            const double error = worstError(rb::kDefaultStepFraction * 0.2);
            THEN("the gradient is right to a few parts in 10⁶ of its size") {
                INFO("expected the gradient within 1e-5·k of the exact one: the error is "
                     << error << ", k = " << wave.k());
                CHECK(error < 1e-5 * wave.k());
            }
        }
    }
}

// [ch11-ramp]
SCENARIO("a planar height ramp tilts the normal by atan(slope)", "[ch11][ex11.1][ex11.2][ex11.3]") {
    GIVEN("the top face (y = 1) of the unit cube, with the ramp h = s·x at strength a") {
        rb::Box box;
        for (const double s : {0.1, 0.5, 1.0, 3.0, 20.0})
            for (const double a : {1.0, 0.25, -2.0}) {
                const auto bump =
                    std::make_shared<rb::Bump>(std::make_shared<rb::RampHeight>(Vec3(s, 0, 0)), a);
                const rb::Material m = bumpedMaterial(bump);
                const rb::Instance cube = rbtest::makeInstance(box, rb::Mat4(1.0), &m);
                WHEN("a ray straight down meets the face at (0.3, 1, 0.6) and the bump of slope "
                     << s << " at strength " << a << " tilts it") {
                    const rb::Ray ray{Vec3(0.3, 3, 0.6), Vec3(0, -2, 0)};
                    rb::Hit hit = hitOf(cube, ray);
                    bump->perturb(ray, hit);
                    THEN(
                        "it leans by atan(a·s) away from uphill, within the plane of slope and "
                        "normal") {
                        // Source: the displaced face y = 1 + a·s·x has the normal
                        // (−a·s, 1, 0) / √(1 + (a·s)²), at angle atan(a·s) from +y.
                        INFO("s = " << s << ", a = " << a);
                        CHECK(angleBetween(hit.ns, hit.ng) ==
                              Approx(std::atan(std::abs(a * s))).margin(1e-9));
                        CHECK(hit.ns.x * a * s < 0.0);
                        CHECK(hit.ns.z == Approx(0.0).margin(1e-12));
                        CHECK(glm::length(hit.ns) == Approx(1.0).epsilon(1e-14));
                    }
                }
            }
    }
    GIVEN("the ramp on a cube under a uniform scale, a rotation and a translation") {
        rb::Box box;
        const double s = 0.7;
        const auto bump =
            std::make_shared<rb::Bump>(std::make_shared<rb::RampHeight>(Vec3(0, 0, s)), 1.0);
        const rb::Material m = bumpedMaterial(bump);
        const rb::Mat4 place = glm::scale(
            glm::rotate(glm::translate(rb::Mat4(1.0), Vec3(4, -2, 7)), 0.8, Vec3(1, 2, 3)),
            Vec3(5.0));
        const rb::Instance cube = rbtest::makeInstance(box, place, &m);
        WHEN("a ray meets the face that was y = 1") {
            const Vec3 target = rb::transformPoint(place, Vec3(0.4, 1.0, 0.3));
            const Vec3 from = rb::transformPoint(place, Vec3(0.5, 4.0, 0.6));
            const rb::Ray ray{from, target - from};
            rb::Hit hit = hitOf(cube, ray);
            bump->perturb(ray, hit);
            THEN("the tilt is still atan(s): a uniform scale changes heights and lengths alike") {
                CHECK(angleBetween(hit.ns, hit.ng) == Approx(std::atan(s)).margin(1e-9));
            }
        }
    }
}
// [ch11-ramp]

// [ch11-lit-ramp]
SCENARIO("a floor with a ramp bump is lit as a tilted floor would be",
         "[ch11][ex11.1][ex11.2][ex11.3]") {
    GIVEN(
        "a white floor stretched 10 × in x and z, a ramp of slope s in object space, a light "
        "straight above the point the camera sees") {
        for (const double s : {0.0, 2.0, 10.0, 40.0}) {
            const std::string lua =
                "local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
                "m:set_bump{pattern = 'ramp', strength = 1, slope = {" +
                std::to_string(s) +
                ", 0, 0}}\n"
                "root = gr.node('root')\n"
                "local floor = gr.cube('floor')\n"
                "floor:scale(10, 1, 10)\n"
                "floor:translate(-5, -1, -5)\n"
                "floor:set_material(m)\n"
                "root:add_child(floor)\n"
                "gr.render(root, 'out.png', 8, 8, {0, 5, 0}, {0, -1, 0}, {0, 0, 1}, 50,\n"
                "          {0, 0, 0}, {gr.light({0.3, 1000, 0.2}, {1, 1, 1}, {1, 0, 0})})\n";
            const auto world = rbtest::worldFromLua(lua, withBump());
            WHEN("the camera ray meets the floor under the light, for the slope s = " << s) {
                const Colour c =
                    rbtest::traceOne(*world, rb::Ray{Vec3(0, 5, 0), Vec3(0.3, -5, 0.2)});
                THEN("the radiance is kd · cos(atan(s / 10))") {
                    // Source: under scale(10, 1, 10) the object-space ramp y = s·x rises by s
                    // over 10 world units, so the world slope is s/10 and the bumped normal
                    // makes the angle atan(s/10) with the vertical light direction; Lambert's
                    // term is its cosine, 1 / √(1 + (s/10)²).
                    INFO("s = " << s);
                    CHECK(c.r == Approx(1.0 / std::sqrt(1.0 + s * s / 100.0)).margin(1e-6));
                }
            }
        }
    }
}
// [ch11-lit-ramp]

// [ch11-zero]
SCENARIO("a zero bump leaves every normal unchanged", "[ch11][ex11.1][ex11.2][ex11.3][ex11.4]") {
    GIVEN("a stretched, turned sphere with ripples and with noise") {
        rb::Sphere sphere;
        rbtest::Rng rng(11);
        const std::vector<std::shared_ptr<const rb::HeightField>> fields = {
            std::make_shared<rb::RippleHeight>(std::vector<Vec3>{Vec3(0.3, 0.9, 0)}, 0.2),
            std::make_shared<rb::NoiseHeight>(0.3, 4, 7)};
        const rb::Mat4 place = rbtest::placeAtScale(2.0, Vec3(1.0, 0.4, 2.0));
        for (size_t k = 0; k < fields.size(); ++k) {
            const rb::Bump zero(fields[k], 0.0), tiny(fields[k], 1e-12);
            const rb::Instance ball = rbtest::makeInstance(sphere, place);
            WHEN("strength 0 and strength 1e-12 of the " << (k == 0 ? "ripples" : "noise")
                                                         << " perturb 200 random hits") {
                THEN("strength 0 keeps ns bit for bit; 1e-12 moves it by less than 1e-10") {
                    for (const rbtest::SurfacePoint& sp : rbtest::sampleSurface(ball, rng, 200)) {
                        rb::Hit a = sp.hit, b = sp.hit;
                        zero.perturb(sp.probe, a);
                        tiny.perturb(sp.probe, b);
                        REQUIRE(a.ns == sp.hit.ns);
                        REQUIRE(angleBetween(b.ns, sp.hit.ns) < 1e-10);
                    }
                }
            }
        }
    }
    GIVEN("a lit scene whose balls carry strength-0 ripples, and the same scene without bumps") {
        const std::string body =
            "root = gr.node('root')\n"
            "for i = 0, 2 do\n"
            "  local b = gr.nh_sphere('b' .. i, {-2 + 2 * i, 0, -3}, 0.9)\n"
            "  b:set_material(m)\n"
            "  root:add_child(b)\n"
            "end\n"
            "gr.render(root, 'out.png', 32, 24, {0, 0, 2}, {0, 0, -1}, {0, 1, 0}, 60,\n"
            "          {0.1, 0.1, 0.1}, {gr.light({2, 4, 3}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n";
        const std::string plain = "local m = gr.material({0.7, 0.3, 0.2}, {0.5, 0.5, 0.5}, 30)\n";
        const auto bumped = rbtest::worldFromLua(
            plain + "m:set_bump{pattern = 'ripples', strength = 0, wavelength = 0.1}\n" + body,
            withBump());
        const auto unbumped = rbtest::worldFromLua(plain + body, withBump());
        THEN("the images are bit-identical") {
            CHECK(bumpStages(*bumped) == 1);
            CHECK(rbtest::bitIdentical(rbtest::renderSmall(*bumped, 32, 24),
                                       rbtest::renderSmall(*unbumped, 32, 24)));
        }
    }
}
// [ch11-zero]

// [ch11-facing]
SCENARIO("the bumped normal never faces away from the viewer, at any strength",
         "[ch11][ex11.1][ex11.2][ex11.3][ex11.4]") {
    GIVEN("a sphere and a box, with ripples and noise, seen from random points outside") {
        rb::Sphere sphere;
        rb::Box box;
        rbtest::Rng rng(1111);
        const std::vector<std::shared_ptr<const rb::HeightField>> fields = {
            std::make_shared<rb::RippleHeight>(std::vector<Vec3>{Vec3(0.2, 1.0, 0.1)}, 0.15),
            std::make_shared<rb::NoiseHeight>(0.25, 5, 3)};
        const std::vector<double> strengths = {1e-3, 0.01,  0.1,  1.0,   10.0,  1e3,
                                               1e6,  1e300, -0.1, -10.0, -1e300};
        int rawFlips = 0, checked = 0;
        for (const rb::Shape* shape :
             {static_cast<const rb::Shape*>(&sphere), static_cast<const rb::Shape*>(&box)}) {
            const rb::Instance instance =
                rbtest::makeInstance(*shape, rbtest::placeAtScale(1.0, Vec3(1.0, 0.5, 1.5)));
            for (const rbtest::SurfacePoint& sp : rbtest::sampleSurface(instance, rng, 150))
                for (const auto& field : fields)
                    for (const double a : strengths) {
                        const rb::Bump bump(field, a);
                        rb::Hit hit = sp.hit;
                        bump.perturb(sp.probe, hit);
                        const Vec3 v = -glm::normalize(sp.probe.d);
                        // The raw formula, without the viewer-side rule, for comparison.
                        const Vec3 xObj = rb::transformPoint(instance.worldToObject, sp.hit.p);
                        const Vec3 nObj = glm::normalize(
                            glm::transpose(rb::Mat3(instance.objectToWorld)) * sp.hit.ns);
                        const Vec3 raw = glm::normalize(
                            instance.normalToWorld *
                            rb::bumpedNormal(
                                nObj, rb::surfaceGradient(*field, xObj, nObj, bump.step()), a));
                        if (glm::dot(raw, v) * glm::dot(sp.hit.ns, v) <= 0.0) ++rawFlips;
                        ++checked;
                        // Source: the probe rays come from outside, so the unbumped normal
                        // (outward) faces the viewer: ns · v > 0 must survive the bump.
                        REQUIRE(glm::dot(sp.hit.ns, v) > 0.0);
                        REQUIRE(rb::isFinite(hit.ns));
                        REQUIRE(glm::length(hit.ns) == Approx(1.0).epsilon(1e-12));
                        REQUIRE(glm::dot(hit.ns, v) > 0.0);
                    }
        }
        THEN("every bumped normal faced the viewer, though the raw formula tipped many over") {
            INFO(rawFlips << " of " << checked << " raw normals faced away");
            CHECK(rawFlips > checked / 10);
        }
    }
}
// [ch11-facing]

// [ch11-gradient]
SCENARIO("the numerical gradient converges to the exact one as the step squared",
         "[ch11][ex11.2][ex11.4]") {
    GIVEN("ripples of wavelength 0.2 around two centres, and 100 points on the plane y = 0.5") {
        const double lambda = 0.2;
        const rb::RippleHeight ripples({Vec3(0.1, 0.0, 0.2), Vec3(-0.6, 0.1, 0.4)}, lambda);
        rbtest::Rng rng(7);
        std::vector<Vec3> points;
        for (int i = 0; i < 100; ++i)
            points.emplace_back(rng.uniform(-1, 1), 0.5, rng.uniform(-1, 1));
        const Vec3 n(0, 1, 0);
        /// The largest error of the numerical surface gradient over the points, at one step.
        const auto worstError = [&](double step) {
            double worst = 0.0;
            for (const Vec3& x : points) {
                const Vec3 exact = ripples.exactGradient(x);
                const Vec3 tangential = exact - glm::dot(exact, n) * n;
                worst = std::max(
                    worst, glm::length(rb::surfaceGradient(ripples, x, n, step) - tangential));
            }
            return worst;
        };
        WHEN("the step halves from λ/20 to λ/40") {
            const double coarse = worstError(lambda / 20), fine = worstError(lambda / 40);
            THEN("the error falls by about 4") {
                // Source: Taylor's theorem: (h(x+ε) − h(x−ε)) / 2ε = h'(x) + ε² h'''(x) / 6 +
                // O(ε⁴), so halving ε quarters the leading error.
                INFO("error " << coarse << " -> " << fine);
                CHECK(coarse / fine == Approx(4.0).epsilon(0.05));
            }
        }
        WHEN("the default step, λ/1000, is used") {
            const double error = worstError(rb::kDefaultStepFraction * lambda);
            const double gradientScale = 2.0 * glm::pi<double>() / lambda;  // |∇h| ≤ k
            THEN("the gradient is right to a few parts in 10⁶ of its size") {
                INFO("error " << error);
                CHECK(error < 1e-5 * gradientScale);
            }
        }
    }
}
// [ch11-gradient]

// [ch11-ripples]
SCENARIO("ripples tilt the normal of a flat pond by their exact slope",
         "[ch11][ex11.1][ex11.2][ex11.3][ex11.4]") {
    GIVEN("a pond: the unit cube's top face with ripples around (0.5, 1, 0.5)") {
        rb::Box box;
        const double lambda = 0.1, a = 0.02;
        const auto ripples =
            std::make_shared<rb::RippleHeight>(std::vector<Vec3>{Vec3(0.5, 1, 0.5)}, lambda);
        const auto bump = std::make_shared<rb::Bump>(ripples, a);
        const rb::Material m = bumpedMaterial(bump);
        const rb::Instance pond = rbtest::makeInstance(box, rb::Mat4(1.0), &m);
        rbtest::Rng rng(5);
        double largestTilt = 0.0;
        for (int i = 0; i < 200; ++i) {
            const Vec3 target(rng.uniform(0.05, 0.95), 1.0, rng.uniform(0.05, 0.95));
            const rb::Ray ray{Vec3(0.5, 3, 2), target - Vec3(0.5, 3, 2)};
            rb::Hit hit = hitOf(pond, ray);
            bump->perturb(ray, hit);
            const Vec3 g = ripples->exactGradient(hit.p);
            const Vec3 expected = glm::normalize(Vec3(0, 1, 0) - a * Vec3(g.x, 0, g.z));
            largestTilt = std::max(largestTilt, angleBetween(expected, Vec3(0, 1, 0)));
            // Source: n' = normalize(n − a ∇h) with ∇h from RippleHeight::exactGradient.
            REQUIRE(angleBetween(hit.ns, expected) < 2e-5);
        }
        THEN("the ripples really tilt it: by up to atan(a·2π/λ) = 0.9 near the centre") {
            CHECK(largestTilt > 0.2);
        }
    }
}
// [ch11-ripples]

SCENARIO("gradient noise is zero on the lattice, bounded and smooth", "[ch11]") {
    GIVEN("noise with seed 3") {
        rbtest::Rng rng(3);
        THEN("it is 0 at integer points (every corner's offset is zero there)") {
            // Source: Perlin 2002: at a lattice point the only weight is that corner's, and
            // its gradient is dotted with a zero offset.
            for (int i = 0; i < 50; ++i) {
                const Vec3 p(std::floor(rng.uniform(-50, 50)), std::floor(rng.uniform(-50, 50)),
                             std::floor(rng.uniform(-50, 50)));
                REQUIRE(rb::gradientNoise(p, 3) == 0.0);
            }
        }
        THEN("it stays within ±1.5, its mean is near 0, and it is not flat") {
            double sum = 0.0, sumSquares = 0.0;
            const int n = 20000;
            for (int i = 0; i < n; ++i) {
                const double v = rb::gradientNoise(
                    Vec3(rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)), 3);
                REQUIRE(std::abs(v) <= 1.5);
                sum += v;
                sumSquares += v * v;
            }
            CHECK(std::abs(sum / n) < 0.02);
            CHECK(sumSquares / n > 0.01);
        }
        THEN("it changes by at most a bounded rate: |N(x + d) − N(x)| ≤ 6 |d|") {
            for (int i = 0; i < 2000; ++i) {
                const Vec3 x(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
                const Vec3 d = 1e-4 * rng.unitVector();
                REQUIRE(std::abs(rb::gradientNoise(x + d, 3) - rb::gradientNoise(x, 3)) <=
                        6.0 * glm::length(d));
            }
        }
        THEN("far beyond any lattice index, and at NaN, it is 0, not undefined behaviour") {
            CHECK(rb::gradientNoise(Vec3(1e300, 0.5, 0.5), 3) == 0.0);
            CHECK(rb::gradientNoise(Vec3(0.5, -1e19, 0.5), 3) == 0.0);
            CHECK(rb::gradientNoise(Vec3(0.5, 0.5, std::nan("")), 3) == 0.0);
        }
        THEN("another seed gives another function") {
            const Vec3 x(0.37, 1.21, -2.5);
            CHECK(rb::gradientNoise(x, 3) != rb::gradientNoise(x, 4));
        }
    }
}

// [ch11-stability]
SCENARIO("a strength that would flip the normal is held on the viewer's side",
         "[ch11][stability][ex11.1][ex11.2][ex11.3]") {
    GIVEN("a ramp of slope 1 on the unit cube's top face, seen at 60° from the normal") {
        rb::Box box;
        const rb::Instance cube = rbtest::makeInstance(box, rb::Mat4(1.0));
        const rb::Ray ray{Vec3(0.5 + 2 * std::sqrt(3.0), 3, 0.5), Vec3(-2 * std::sqrt(3.0), -2, 0)};
        for (const double a : {2.0, 10.0, 1e8, 1e300, std::numeric_limits<double>::max()}) {
            const rb::Bump bump(std::make_shared<rb::RampHeight>(Vec3(1, 0, 0)), a);
            rb::Hit hit = hitOf(cube, ray);
            const Vec3 v = -glm::normalize(ray.d);
            WHEN("the strength is " << a) {
                // Source: the raw normal (−a, 1, 0)/√(1 + a²) leans away from a viewer on the
                // +x side, v = (√3/2, 1/2, 0): its cosine with v is (1/2 − a√3/2)/√(1 + a²),
                // negative for every a > 1/√3.
                const Vec3 raw = rb::bumpedNormal(Vec3(0, 1, 0), Vec3(1, 0, 0), a);
                bump.perturb(ray, hit);
                THEN(
                    "the raw normal faces away; the bumped one grazes at cos = kMinCosView on our "
                    "side") {
                    CHECK(glm::dot(raw, v) < 0.0);
                    REQUIRE(rb::isFinite(hit.ns));
                    CHECK(glm::dot(hit.ns, v) == Approx(rb::kMinCosView).margin(1e-12));
                }
            }
        }
    }
    GIVEN("height fields whose values or slopes are NaN, Inf or near the largest double") {
        rb::Box box;
        const rb::Instance cube = rbtest::makeInstance(box, rb::Mat4(1.0));
        const rb::Ray ray{Vec3(0.3, 3, 0.4), Vec3(0.1, -2, 0.1)};
        for (const double slope : {std::nan(""), std::numeric_limits<double>::infinity(), 1e308}) {
            const rb::Bump bump(std::make_shared<ConstantJunk>(slope), 1e300);
            rb::Hit hit = hitOf(cube, ray);
            bump.perturb(ray, hit);
            THEN("the normal is finite, unit length, and faces the viewer, for the slope "
                 << slope) {
                REQUIRE(rb::isFinite(hit.ns));
                CHECK(glm::length(hit.ns) == Approx(1.0).epsilon(1e-12));
                CHECK(glm::dot(hit.ns, -glm::normalize(ray.d)) > 0.0);
            }
        }
    }
    GIVEN("a rendered scene with huge bumps: noise at strength 1e6 on a mirror ball and a floor") {
        const auto world = rbtest::worldFromLua(
            "local m = gr.material{kd = {0.6, 0.6, 0.6}, ks = {0.5, 0.5, 0.5}, shininess = 20,"
            " reflect = 0.5}\n"
            "m:set_bump{pattern = 'noise', strength = 1e6, scale = 0.2}\n"
            "root = gr.node('root')\n"
            "local b = gr.nh_sphere('b', {0, 0, -3}, 1)\n"
            "b:set_material(m)\n"
            "root:add_child(b)\n"
            "local f = gr.nh_box('f', {-5, -12, -8}, 10)\n"
            "f:set_material(m)\n"
            "root:add_child(f)\n"
            "gr.render(root, 'out.png', 32, 24, {0, 0, 2}, {0, 0, -1}, {0, 1, 0}, 60,\n"
            "          {0.1, 0.1, 0.1}, {gr.light({2, 4, 3}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n",
            withBump());
        THEN("every pixel is finite and non-negative") {
            CHECK(rbtest::allFiniteNonNegative(rbtest::renderSmall(*world, 32, 24)));
        }
    }
}
// [ch11-stability]

// [ch11-lua]
SCENARIO("material:set_bump reads raybook's bump table, and refuses what it cannot use",
         "[ch11][ex11.4]") {
    GIVEN("materials with each pattern") {
        const auto bumpOf = [](const std::string& call) {
            const rb::Material m = rbtest::materialOf(
                "gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)\nm:set_bump" + call, withBump());
            REQUIRE(m.bump != nullptr);
            return std::dynamic_pointer_cast<const rb::Bump>(m.bump);
        };
        THEN("the strength, the step and the pattern are read") {
            const auto ripples = bumpOf("{pattern = 'ripples', strength = 0.02, wavelength = 0.5}");
            REQUIRE(ripples);
            CHECK(ripples->strength() == 0.02);
            CHECK(ripples->step() == Approx(0.5 * rb::kDefaultStepFraction));
            const auto noise = bumpOf(
                "{pattern = 'noise', strength = -1, scale = 2, octaves = 2,"
                " seed = 9, step = 0.001}");
            CHECK(noise->strength() == -1.0);
            CHECK(noise->step() == 0.001);
            const auto ramp = bumpOf("{pattern = 'ramp', strength = 3, slope = {1, 2, 3}}");
            CHECK(dynamic_cast<const rb::RampHeight&>(ramp->field()).slope() == Vec3(1, 2, 3));
            const auto two = bumpOf(
                "{pattern = 'ripples', strength = 1, wavelength = 1, centres = {{0, 0, 0}, {1, 0, "
                "0}}}");
            CHECK(two->field().height(Vec3(0.5, 0, 0)) ==
                  Approx(2.0 * std::sin(glm::pi<double>()) / std::sqrt(1.5)).margin(1e-12));
        }
    }
    GIVEN("bad bump tables") {
        const auto error = [](const std::string& call) {
            return rbtest::loadError(
                rbtest::oneMaterialScene("gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)",
                                         "m:set_bump" + call + "\n"),
                withBump());
        };
        THEN("each error names the call and what was expected, with the line") {
            CHECK_THAT(error("{pattern = 'waves', strength = 1}"),
                       Contains("scene.lua:6:") && Contains("unknown pattern 'waves'"));
            CHECK_THAT(error("{pattern = 'ripples', wavelength = 1}"),
                       Contains("field 'strength' is required"));
            CHECK_THAT(error("{pattern = 'ripples', strength = 1, wavelength = 0}"),
                       Contains("'wavelength' must be positive"));
            CHECK_THAT(error("{pattern = 'ripples', strength = 0/0, wavelength = 1}"),
                       Contains("field 'strength' must be finite"));
            CHECK_THAT(error("{pattern = 'noise', strength = 1, octaves = 9}"),
                       Contains("'octaves' must be a whole number from 1 to 8"));
            CHECK_THAT(error("{pattern = 'noise', strength = 1, wavelength = 1}"),
                       Contains("unknown field 'wavelength' for pattern 'noise'"));
            CHECK_THAT(error("{pattern = 'ramp', strength = 1, step = -1, slope = {1, 0, 0}}"),
                       Contains("'step' must be positive"));
            CHECK_THAT(error("{pattern = 'ramp', strength = 1}"), Contains("'slope' is required"));
            CHECK_THAT(error("('bumps.png', 2, 3)"), Contains("expects one table"));
        }
    }
    GIVEN("a build of chapters 1 to 8") {
        THEN("set_bump names the chapter that provides it") {
            CHECK_THAT(rbtest::loadError(
                           rbtest::oneMaterialScene("gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)",
                                                    "m:set_bump{pattern = 'ramp', strength = 1}\n"),
                           rbtest::chapters(8)),
                       Contains("method 'set_bump' needs chapter 11 (bump)"));
        }
    }
}
// [ch11-lua]

// [ch11-costs-nothing]
SCENARIO("without bumps, or with the feature off, the chapter changes nothing",
         "[ch11][ex11.1][ex11.2][ex11.3][ex11.4]") {
    const std::string body =
        "root = gr.node('root')\n"
        "local b = gr.nh_sphere('b', {0, 0, -3}, 1)\n"
        "b:set_material(m)\n"
        "root:add_child(b)\n"
        "local f = gr.nh_box('f', {-5, -12, -8}, 10)\n"
        "f:set_material(gr.material({0.4, 0.5, 0.6}, {0.2, 0.2, 0.2}, 10))\n"
        "root:add_child(f)\n"
        "gr.render(root, 'out.png', 32, 24, {0, 0, 2}, {0, 0, -1}, {0, 1, 0}, 60,\n"
        "          {0.1, 0.1, 0.1}, {gr.light({2, 4, 3}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n";
    const std::string plain = "local m = gr.material({0.7, 0.3, 0.2}, {0.5, 0.5, 0.5}, 30)\n";
    const std::string rippled = plain +
                                "m:set_bump{pattern = 'ripples', strength = 0.02, wavelength = 0.2,"
                                " centre = {0.3, 0.5, 0.8}}\n";
    GIVEN("a scene without bumps") {
        const auto eleven = rbtest::worldFromLua(plain + body, withBump());
        const auto eight = rbtest::worldFromLua(plain + body, rbtest::chapters(8));
        THEN("the chapter installs nothing, and the image is the chapter-8 build's, bit for bit") {
            CHECK(bumpStages(*eleven) == 0);
            CHECK(rbtest::bitIdentical(rbtest::renderSmall(*eleven, 32, 24),
                                       rbtest::renderSmall(*eight, 32, 24)));
        }
    }
    GIVEN("a scene with ripples on the ball") {
        const auto on = rbtest::worldFromLua(rippled + body, withBump());
        const auto off = rbtest::worldFromLua(rippled + body, rbtest::chapters(11, "all,-bump"));
        const auto none = rbtest::worldFromLua(plain + body, withBump());
        THEN("--features=all,-bump renders it as if it had no bump; with bumps it differs") {
            CHECK(bumpStages(*off) == 0);
            CHECK(rbtest::bitIdentical(rbtest::renderSmall(*off, 32, 24),
                                       rbtest::renderSmall(*none, 32, 24)));
            CHECK_FALSE(rbtest::bitIdentical(rbtest::renderSmall(*on, 32, 24),
                                             rbtest::renderSmall(*none, 32, 24)));
        }
        THEN("the bumped image is the same on 1 and 2 threads") {
            rb::RayCounters c1, c2;
            rb::RenderSettings oneThread, twoThreads;
            oneThread.threads = 1;
            twoThreads.threads = 2;
            const rb::Image one = rbtest::renderAt(*on, 32, 24, oneThread, c1);
            const rb::Image two = rbtest::renderAt(*on, 32, 24, twoThreads, c2);
            CHECK(rbtest::bitIdentical(one, two));
        }
    }
}
// [ch11-costs-nothing]

// [ch11-height-map]
SCENARIO("a height map of a linear ramp tilts the normal by atan(slope)",
         "[ch11][ex11.1][ex11.3]") {
    rbtest::TempDir dir;
    const std::string ramp = writeRampPng(dir);
    const auto heights = std::make_shared<rb::HeightImage>(*rb::loadTextureImage(ramp));
    // Source: column x holds level x, so the height rises by 1/255 per texel of 1/256 in u:
    // dh/du = 256/255.
    const double dh_du = 256.0 / 255.0;
    GIVEN("the image read as heights") {
        THEN("texel x holds x/255 as the file stores it, bilinear between texel centres") {
            CHECK(heights->at(rb::Vec2((10 + 0.5) / 256, 0.5)) == Approx(10 / 255.0).margin(1e-6));
            CHECK(heights->at(rb::Vec2((10 + 0.75) / 256, 0.5)) ==
                  Approx(10.25 / 255.0).margin(1e-6));
        }
    }
    GIVEN("the unit cube's top face, where u runs along +x over one unit") {
        rb::Box box;
        const rb::Instance cube = rbtest::makeInstance(box, rb::Mat4(1.0));
        for (const double a : {1.0, 0.3, -2.0}) {
            const rb::HeightMapBump bump(heights, a, 1.0);
            const rb::Ray ray{Vec3(0.37, 3, 0.6), Vec3(0, -1, 0)};
            rb::Hit hit = hitOf(cube, ray);
            bump.perturb(ray, hit);
            THEN("the normal leans by atan(a · 256/255) away from uphill (+x), for a = " << a) {
                CHECK(angleBetween(hit.ns, hit.ng) ==
                      Approx(std::atan(std::abs(a) * dh_du)).margin(1e-5));
                CHECK(hit.ns.x * a < 0.0);
            }
        }
    }
    GIVEN("the same face with the image repeated twice along u (scale = {2, 1})") {
        rb::Box box;
        const rb::Instance cube = rbtest::makeInstance(box, rb::Mat4(1.0));
        const rb::HeightMapBump bump(heights, 0.4, 1.0, rb::UVMapping::Surface, rb::Vec2(2, 1));
        const rb::Ray ray{Vec3(0.37, 3, 0.6), Vec3(0, -1, 0)};
        rb::Hit hit = hitOf(cube, ray);
        bump.perturb(ray, hit);
        THEN("the slope doubles: atan(0.4 · 2 · 256/255)") {
            // Source: s = 2u, so dh/du = 2 dh/ds.
            CHECK(angleBetween(hit.ns, hit.ng) == Approx(std::atan(0.4 * 2 * dh_du)).margin(1e-5));
        }
    }
    GIVEN("the unit sphere at its equator, where dp/du has length 2π") {
        rb::Sphere sphere;
        const rb::Instance ball = rbtest::makeInstance(sphere, rb::Mat4(1.0));
        const rb::HeightMapBump bump(heights, 1.0, 1.0);
        const rb::Ray ray{Vec3(0, 0, -3), Vec3(0, 0, 1)};  // meets (0, 0, −1): u = 1/4
        rb::Hit hit = hitOf(ball, ray);
        bump.perturb(ray, hit);
        THEN("the tilt is atan(256/255 / 2π): the same height change over 2π times the length") {
            CHECK(angleBetween(hit.ns, hit.ng) ==
                  Approx(std::atan(dh_du / (2.0 * glm::pi<double>()))).margin(1e-5));
        }
    }
    GIVEN("any two independent tangents dp/du and dp/dv, and derivatives h_u, h_v") {
        rbtest::Rng rng(9);
        for (int i = 0; i < 100; ++i) {
            const Vec3 n = rng.unitVector();
            Vec3 t, b;
            rb::tangentFrame(n, t, b);
            const Vec3 dpdu = rng.uniform(0.1, 3) * t + rng.uniform(-1, 1) * b;
            const Vec3 dpdv = rng.uniform(-1, 1) * t + rng.uniform(0.1, 3) * b;
            const double h_u = rng.uniform(-2, 2), h_v = rng.uniform(-2, 2);
            const Vec3 g = rb::heightMapGradient(h_u, h_v, dpdu, dpdv, n);
            // Source: the surface gradient g is the tangent vector with g · dp/du = ∂h/∂u
            // and g · dp/dv = ∂h/∂v (the chain rule along each parameter line).
            REQUIRE(glm::dot(g, dpdu) == Approx(h_u).margin(1e-12));
            REQUIRE(glm::dot(g, dpdv) == Approx(h_v).margin(1e-12));
            REQUIRE(glm::dot(g, n) == Approx(0.0).margin(1e-12));
        }
    }
    GIVEN("seed 002's set_bump_map and raybook's pattern 'image' in a scene") {
        const auto bumpOf = [&](const std::string& call, const rb::FeatureSet& features) {
            const auto renders = rbtest::loadSceneText(
                rbtest::oneMaterialScene("gr.material({1, 1, 1}, {0, 0, 0}, 1)", call + "\n"),
                features);
            return renders.at(0).instances.at(0).material->bump;
        };
        THEN("set_bump_map takes the default strength, the table its own, and both the image") {
            const auto seed = std::dynamic_pointer_cast<const rb::HeightMapBump>(
                bumpOf("m:set_bump_map('" + ramp + "')", withBump()));
            REQUIRE(seed);
            CHECK(seed->strength() == rb::kDefaultHeightMapStrength);
            CHECK(seed->step() == 1.0);
            CHECK(seed->image().width() == 256);
            const auto own = std::dynamic_pointer_cast<const rb::HeightMapBump>(
                bumpOf("m:set_bump{pattern = 'image', file = '" + ramp +
                           "', strength = 0.5, step = 2, mapping = 'cylindrical', scale = {3, 1}}",
                       withBump()));
            REQUIRE(own);
            CHECK(own->strength() == 0.5);
            CHECK(own->step() == 2.0);
        }
        THEN("a missing image, a missing file name and a chapter-10 build are refused") {
            CHECK_THAT(rbtest::loadError(
                           rbtest::oneMaterialScene("gr.material({1, 1, 1}, {0, 0, 0}, 1)",
                                                    "m:set_bump_map('no-such-heights.png')\n"),
                           withBump()),
                       Contains("scene.lua:6:") && Contains("no-such-heights.png"));
            CHECK_THAT(rbtest::loadError(rbtest::oneMaterialScene(
                                             "gr.material({1, 1, 1}, {0, 0, 0}, 1)",
                                             "m:set_bump{pattern = 'image', strength = 1}\n"),
                                         withBump()),
                       Contains("field 'file' must be an image file name"));
            CHECK_THAT(
                rbtest::loadError(rbtest::oneMaterialScene(
                                      "gr.material({1, 1, 1}, {0, 0, 0}, 1)",
                                      "m:set_bump{pattern = 'image', strength = 1, file = '" +
                                          ramp + "', mapping = 'cubic'}\n"),
                                  withBump()),
                Contains("field 'mapping' must be 'surface', 'planar', 'spherical' or "
                         "'cylindrical'"));
            CHECK_THAT(
                rbtest::loadError(rbtest::oneMaterialScene(
                                      "gr.material({1, 1, 1}, {0, 0, 0}, 1)",
                                      "m:set_bump{pattern = 'image', strength = 1, file = '" +
                                          ramp + "', scale = {0, 1}}\n"),
                                  withBump()),
                Contains("field 'scale' must not be 0"));
            CHECK_THAT(
                rbtest::loadError(rbtest::oneMaterialScene("gr.material({1, 1, 1}, {0, 0, 0}, 1)",
                                                           "m:set_bump_map('" + ramp + "')\n"),
                                  rbtest::chapters(10)),
                Contains("method 'set_bump_map' needs chapter 11 (bump)"));
        }
    }
    GIVEN("a lit floor with the ramp map at strength 0.5 under a light straight above") {
        const std::string lua =
            "local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
            "m:set_bump{pattern = 'image', file = '" +
            ramp +
            "', strength = 0.5}\n"
            "root = gr.node('root')\n"
            "local floor = gr.cube('floor')\n"
            "floor:set_material(m)\n"
            "root:add_child(floor)\n"
            "gr.render(root, 'out.png', 8, 8, {0.4, 5, 0.5}, {0, -1, 0}, {0, 0, 1}, 50,\n"
            "          {0, 0, 0}, {gr.light({0.4, 1000, 0.5}, {1, 1, 1}, {1, 0, 0})})\n";
        const auto on = rbtest::worldFromLua(lua, withBump());
        const auto off = rbtest::worldFromLua(lua, rbtest::chapters(11, "all,-bump"));
        const rb::Ray ray{Vec3(0.4, 5, 0.5), Vec3(0, -1, 0)};
        THEN("it is lit as a floor tilted by atan(0.5 · 256/255); with the feature off, flat") {
            CHECK(rbtest::traceOne(*on, ray).r ==
                  Approx(1.0 / std::sqrt(1.0 + 0.25 * dh_du * dh_du)).margin(1e-5));
            CHECK(rbtest::traceOne(*off, ray).r == Approx(1.0).margin(1e-12));
        }
    }
}
// [ch11-height-map]

// [ch11-height-map-v]
SCENARIO("a height map that rises towards the image's top tilts the normal down, away from +v",
         "[ch11][ex11.1][ex11.3]") {
    rbtest::TempDir dir;
    const auto heights =
        std::make_shared<rb::HeightImage>(*rb::loadTextureImage(writeUpwardRampPng(dir)));
    // Source: the file's top row (y = 0) is v = 1 and holds level 255, row y holds 255 − y, so
    // the height rises by 1/255 per texel of 1/256 in v: h = (256 v − 0.5)/255, dh/dv = 256/255.
    const double dh_dv = 256.0 / 255.0;
    GIVEN("the image read as heights") {
        THEN("the bottom rows (small v) are low and the top rows high") {
            CHECK(heights->at(rb::Vec2(0.5, (10 + 0.5) / 256)) == Approx(10 / 255.0).margin(1e-6));
            CHECK(heights->at(rb::Vec2(0.5, (245 + 0.5) / 256)) ==
                  Approx(245 / 255.0).margin(1e-6));
        }
    }
    GIVEN("the unit cube's front face (z = 1), where u runs along +x and v up along +y") {
        rb::Box box;
        const rb::Instance cube = rbtest::makeInstance(box, rb::Mat4(1.0));
        const rb::Ray ray{Vec3(0.37, 0.6, 3), Vec3(0, 0, -1)};
        THEN("at strength a the normal leans by atan(a · 256/255 / |dp/dv|), |dp/dv| = 1, down") {
            for (const double a : {1.0, 0.3, -2.0}) {
                const rb::HeightMapBump bump(heights, a, 1.0);
                rb::Hit hit = hitOf(cube, ray);
                bump.perturb(ray, hit);
                // Source: n' ∝ n − a·(dh/dv)·∇v with ∇v = dp/dv / |dp/dv|² = +y, so
                // n' ∝ (0, −a·256/255, 1): the tilt is atan(|a|·256/255) and n'.y has a's
                // opposite sign; nothing varies along u, so n'.x = 0.
                INFO("a = " << a);
                CHECK(angleBetween(hit.ns, hit.ng) ==
                      Approx(std::atan(std::abs(a) * dh_dv)).margin(1e-5));
                CHECK(hit.ns.y * a < 0.0);
                CHECK(hit.ns.x == Approx(0.0).margin(1e-12));
            }
        }
    }
    GIVEN("the unit sphere at its equator, where dp/dv points up (+y) with length π") {
        rb::Sphere sphere;
        const rb::Instance ball = rbtest::makeInstance(sphere, rb::Mat4(1.0));
        const rb::HeightMapBump bump(heights, 1.0, 1.0);
        const rb::Ray ray{Vec3(0, 0, -3), Vec3(0, 0, 1)};  // meets (0, 0, −1): v = 1/2
        rb::Hit hit = hitOf(ball, ray);
        bump.perturb(ray, hit);
        THEN("the normal leans down by atan(256/255 / π)") {
            // Source: v = θ/π with θ from the south pole, so dp/dv = π·(+y) at the equator and
            // the slope along the surface is (dh/dv)/|dp/dv| = (256/255)/π.
            CHECK(angleBetween(hit.ns, hit.ng) ==
                  Approx(std::atan(dh_dv / glm::pi<double>())).margin(1e-5));
            CHECK(hit.ns.y < 0.0);
        }
    }
}
// [ch11-height-map-v]

// [ch11-height-map-stability]
SCENARIO("a height map steep enough to flip the normal is held on the viewer's side",
         "[ch11][stability][ex11.1][ex11.3]") {
    rbtest::TempDir dir;
    const auto heights =
        std::make_shared<rb::HeightImage>(*rb::loadTextureImage(writeRampPng(dir)));
    GIVEN("the ramp map at strengths that flip the raw normal, seen from the uphill side") {
        rb::Box box;
        const rb::Instance cube = rbtest::makeInstance(box, rb::Mat4(1.0));
        // Source: the bumped normal leans to −x by atan(a · 256/255); seen from +x at 60° from
        // the normal, v = (√3/2, 1/2, 0), it faces away once a · 256/255 > 1/√3.
        const rb::Ray ray{Vec3(0.5 + 2 * std::sqrt(3.0), 3, 0.5), Vec3(-2 * std::sqrt(3.0), -2, 0)};
        for (const double a : {1.0, 1e6, 1e300}) {
            const rb::HeightMapBump bump(heights, a, 1.0);
            rb::Hit hit = hitOf(cube, ray);
            bump.perturb(ray, hit);
            THEN("the normal is finite and held at cos = kMinCosView on the viewer's side, for a = "
                 << a) {
                REQUIRE(rb::isFinite(hit.ns));
                CHECK(glm::dot(hit.ns, -glm::normalize(ray.d)) ==
                      Approx(rb::kMinCosView).margin(1e-9));
            }
        }
    }
}
// [ch11-height-map-stability]

// [ch11-stage]
SCENARIO("a bump is a shading-normal stage that runs after chapter 9's smooth normals",
         "[ch11][ex11.1][ex11.2][ex11.4]") {
    GIVEN("the icosphere as a rippled smooth mesh") {
        const std::string asset = rbtest::sourceDir() + "/scenes/assets/icosphere80.obj";
        auto scene = [&](const std::string& call, const std::string& bump) {
            return "local m = gr.material({0.7, 0.6, 0.5}, {0.5, 0.5, 0.5}, 25)\n" + bump +
                   "root = gr.node('root')\nlocal s = " + call + "('s', '" + asset +
                   "')\ns:set_material(m)\nroot:add_child(s)\n"
                   "gr.render(root, 'out.png', 40, 40, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 40,"
                   " {0.1, 0.1, 0.1}, {gr.light({-5, 2, 1}, {1, 1, 1}, {1, 0, 0})})\n";
        };
        const std::string ripples =
            "m:set_bump{pattern = 'ripples', strength = 0.01, wavelength = 0.3}\n";
        const auto smoothBumped =
            rbtest::worldFromLua(scene("gr.smooth_mesh", ripples), withBump());
        THEN("the pipeline has one list of normal stages: the smooth normals, then the bump") {
            REQUIRE(smoothBumped->pipeline.normals.size() == 2);
            CHECK(dynamic_cast<const rb::BumpNormals*>(smoothBumped->pipeline.normals[0].get()) ==
                  nullptr);
            CHECK(dynamic_cast<const rb::BumpNormals*>(smoothBumped->pipeline.normals[1].get()) !=
                  nullptr);
        }
        THEN(
            "the bump tilts the smooth normal: the image differs from the bumped faceted mesh "
            "and from the unbumped smooth mesh") {
            const rb::Image bumped = rbtest::renderSmall(*smoothBumped, 40, 40);
            const rb::Image facetedBumped = rbtest::renderSmall(
                *rbtest::worldFromLua(scene("gr.mesh", ripples), withBump()), 40, 40);
            const rb::Image smooth = rbtest::renderSmall(
                *rbtest::worldFromLua(scene("gr.smooth_mesh", ""), withBump()), 40, 40);
            CHECK_FALSE(rbtest::bitIdentical(bumped, facetedBumped));
            CHECK_FALSE(rbtest::bitIdentical(bumped, smooth));
        }
    }
}
// [ch11-stage]
