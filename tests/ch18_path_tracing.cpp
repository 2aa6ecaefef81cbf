/// \file
/// Chapter 18 tests: path tracing.
///
/// Chapter 18 claims that its path tracer solves the rendering equation without bias, so that
/// the other Monte Carlo chapters can be measured against it. The tests check the estimator
/// against closed forms and against itself: a white furnace (a closed sphere of albedo ρ that
/// emits Le reads Le/(1 − ρ)) at ρ = 0.5, 0.9 and 0.99; the inside of a diffuse sphere lit by a
/// point light at its centre (ρ I / (R² (1 − ρ))); chapter 17's media in the same loop (an
/// albedo-1 medium under a uniform sky returns the sky); light sampling alone, BSDF sampling
/// alone and MIS give the same mean (z-tests) and MIS's variance is at most 1.1× the better
/// one's, region by region; Russian roulette changes the variance and not the mean; Whitted's
/// direct light where there is no indirect light. The normalized Phong lobe's albedo is 1 at
/// normal incidence and at most 1 elsewhere (numerical cubature), and the samplers pass the
/// sampling lab's chi-square. End to end: the same bits on one thread and two, nothing
/// installed for a scene that does not ask, emitters that glow under Whitted, and bad input
/// refused. Random streams use seed 1 (RB_CH18_SEED re-runs them on other streams).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "core/camera.h"
#include "lab/warp_test.h"
#include "media/density.h"
#include "media/medium.h"
#include "path_tracing/bsdf.h"
#include "path_tracing/path_tracing.h"
#include "test_helpers.h"
#include "test_messages.h"

using Catch::Contains;
using rb::Colour;
using rb::Vec3;
using rbtest::meanAndError;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The seed of every random stream in this file: 1, or RB_CH18_SEED.
std::uint64_t seed() {
    return rbtest::seedFromEnv("RB_CH18_SEED");
}

/// Run the world's pre-passes (the path tracer gathers its emitters there), as rb::render does.
void runPrePasses(rbtest::TestWorld& world) {
    const rb::RenderJob job;
    const rb::PinholeCamera camera(job.camera, 8, 8);
    rb::RayCounters counters;
    for (const auto& pass : world.pipeline.prePasses)
        pass->run(world.scene, world.pipeline, {seed(), camera, 8, 8, nullptr, counters});
}

/// The green channel of path i along `ray`, on stream (seed, i, 0).
double pathSample(const rbtest::TestWorld& world, const rb::Ray& ray, int i) {
    const rb::Integrator integrator(world.scene, world.pipeline);
    rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 0);
    rb::RayCounters counters;
    return integrator.trace(ray, sampler, counters, 0).g;
}

/// The mean and standard error of n paths that leave the origin in random directions (path i
/// on stream (seed, i, 0)): what the closed rooms of this file see from their centres.
std::pair<double, double> fromCentre(const rbtest::TestWorld& world, int n) {
    rbtest::Rng rng(seed());
    std::vector<Vec3> directions;
    for (int i = 0; i < n; ++i) directions.push_back(rng.unitVector());
    return meanAndError(n, [&](int i) {
        return pathSample(world, rb::Ray{Vec3(0.0), directions[i]}, i);
    });
}

/// Path-tracing options for TestWorld::build, with `more` added.
std::map<std::string, std::string> pathOptions(std::map<std::string, std::string> more = {}) {
    more["integrator"] = "path";
    return more;
}

}  // namespace

SCENARIO(
    "The power heuristic trusts each technique where its density is the higher, and the "
    "two weights add to 1",
    "[ch18][ex18.1]") {
    // Source: w_a = p_a² / (p_a² + p_b²) (Veach 1997, §9.2.4): w(1, 1) = 1/2, w(2, 1) = 4/5,
    // w(1, 3) = 1/10; a technique the other cannot reproduce (p_b = 0) gets all of the weight.
    GIVEN("pairs of densities") {
        THEN("the weights are the closed form's, and each pair's two weights add to 1") {
            CHECK(rb::powerHeuristic(1.0, 1.0) == Approx(0.5));
            CHECK(rb::powerHeuristic(2.0, 1.0) == Approx(0.8));
            CHECK(rb::powerHeuristic(1.0, 3.0) == Approx(0.1));
            CHECK(rb::powerHeuristic(5.0, 0.0) == Approx(1.0));
            for (const double a : {0.01, 0.3, 2.0, 70.0})
                for (const double b : {0.02, 1.0, 9.0})
                    CHECK(rb::powerHeuristic(a, b) + rb::powerHeuristic(b, a) == Approx(1.0));
        }
    }
}

SCENARIO("A white furnace: a closed sphere of albedo ρ that emits Le reads Le / (1 − ρ)",
         "[ch18][ex18.1][ex18.3][ex18.4]") {
    // Source: inside a closed sphere every point sees only the wall, so the radiance L is the
    // same everywhere and in every direction: L = Le + ρ L, hence L = Le / (1 − ρ) (the
    // furnace test of pbrt-v4's integrator tests, there at ±2.5%; here a z-test).
    const double rhos[] = {0.5, 0.9, 0.99};
    for (const double rho : rhos) {
        GIVEN("a unit sphere of kd = " + std::to_string(rho) + " emitting 0.5, seen from inside") {
            rbtest::TestWorld world;
            rb::Material wall;
            wall.kd = Colour(rho);
            wall.emission = Colour(0.5);
            world.addSphere(rb::Mat4(1.0), world.material(wall));
            world.build(rbtest::chapters(18), -1, pathOptions({{"path-depth", "1000000"}}));
            runPrePasses(world);
            WHEN("paths start from its centre in random directions") {
                const auto [mean, error] = fromCentre(world, rho > 0.95 ? 4000 : 20000);
                const double expected = 0.5 / (1.0 - rho);
                THEN("the mean is Le / (1 − ρ) within the z-bound") {
                    INFO("mean " << mean << " ± " << error << ", expected " << expected);
                    CHECK(std::abs(mean - expected) <=
                          rbtest::zCritical(rb::sidak(0.01, 3)) * error);
                    // And the error bound is tight enough to mean something: 2%.
                    CHECK(error < 0.02 * expected);
                }
            }
        }
    }
}

SCENARIO("Light bounces inside a diffuse sphere lit from its centre as the closed form says",
         "[ch18][ex18.3]") {
    // Source: a point light I with falloff {0, 0, 1} (I / r²) at the centre of a sphere of
    // radius R gives every wall point the direct radiance ρ I / R² in A4's units (cos θ = 1
    // everywhere); the wall then sees only
    // wall of that same radiance L, which it reflects as ρ L, so L = ρ I / R² + ρ L:
    // L = ρ I / (R² (1 − ρ)). For ρ = 0.5, I = 1, R = 2: 0.25.
    GIVEN(
        "a sphere of radius 2 and kd = 0.5 with a point light of intensity 1 / r² at its centre") {
        rbtest::TestWorld world;
        rb::Material wall;
        wall.kd = Colour(0.5);
        world.addSphere(glm::scale(rb::Mat4(1.0), Vec3(2.0)), world.material(wall));
        rb::PointLight light;
        light.falloff = Vec3(0.0, 0.0, 1.0);
        world.scene.lights.push_back(light);
        world.build(rbtest::chapters(18), -1, pathOptions({{"path-depth", "1000000"}}));
        runPrePasses(world);
        WHEN("paths leave the centre in random directions") {
            const auto [mean, error] = fromCentre(world, 20000);
            THEN("the wall reads 0.25 within the z-bound") {
                INFO("mean " << mean << " ± " << error);
                CHECK(std::abs(mean - 0.25) <= rbtest::zCritical(0.01) * error);
                CHECK(error < 0.005);
            }
        }
    }
}

SCENARIO(
    "Chapter 17's media run in the same path loop: an albedo-1 medium under a uniform sky "
    "gives back the sky",
    "[ch18]") {
    // Source: with no absorption and a sky of radiance 1 on every side, radiance is 1
    // everywhere inside and in every direction, whatever the density (chapter 17's furnace);
    // the path tracer's loop must agree, Russian roulette included (a z-test, since roulette
    // makes single paths differ from 1).
    GIVEN("a unit ball of σs = 5, g = 0.5, seen from its centre, under a sky of 1") {
        rb::Medium medium;
        medium.sigmaA = Colour(0.0);
        medium.sigmaS = Colour(5.0);
        medium.g = 0.5;
        medium.density = std::make_shared<rb::ConstantDensity>();
        rbtest::TestWorld world;
        world.addSphere(rb::Mat4(1.0), nullptr, "ball");
        rb::Instance& ball = world.scene.instances.back();
        ball.medium = &medium;
        ball.mediumBoundaryOnly = true;
        ball.mediumIndex = 0;
        world.scene.background = Colour(1.0);
        world.build(rbtest::chapters(18), -1, pathOptions({{"path-depth", "1000000"}}));
        runPrePasses(world);
        WHEN("paths start in random directions") {
            const auto [mean, error] = fromCentre(world, 20000);
            THEN("they return the sky's radiance, 1, within the z-bound") {
                INFO("mean " << mean << " ± " << error);
                CHECK(std::abs(mean - 1.0) <= rbtest::zCritical(0.01) * error);
            }
        }
    }
}

namespace {

/// A glossy plate (kd 0.1, ks 0.6, shininess `n`) under two emitting balls, a small bright one
/// and a large dim one, in the spirit of Veach's plates: light sampling wins for the large
/// ball on a rough plate, BSDF sampling for the small bright ball seen in a sharp one.
void veachScene(rbtest::TestWorld& world, double n, const std::string& strategy) {
    rb::Material plate;
    plate.kd = Colour(0.1);
    plate.ks = Colour(0.6);
    plate.shininess = n;
    world.addBox(rbtest::boxFromTo(Vec3(-4, -0.1, -4), Vec3(4, 0, 4)), world.material(plate));
    rb::Material bright, dim;
    bright.emission = Colour(400.0);
    dim.emission = Colour(1.0);
    world.addSphere(glm::scale(glm::translate(rb::Mat4(1.0), Vec3(-1.0, 1.5, -2.0)), Vec3(0.05)),
                    world.material(bright));
    world.addSphere(glm::scale(glm::translate(rb::Mat4(1.0), Vec3(1.5, 1.5, -2.0)), Vec3(0.8)),
                    world.material(dim));
    // Direct light only: the second bounce ends every path.
    world.build(rbtest::chapters(18), -1,
                pathOptions({{"path-depth", "2"}, {"path-strategy", strategy}}));
    runPrePasses(world);
}

}  // namespace

SCENARIO(
    "MIS gives the same mean as light sampling and BSDF sampling, with no more variance "
    "than the better of the two",
    "[ch18][ex18.1][ex18.2][ex18.3][ex18.4]") {
    // Source: each of the three estimators is unbiased for the same direct light (Veach 1997,
    // §9.2), so their means agree; the power heuristic's variance is close to the better
    // technique's wherever one technique is good (Veach's Theorem 9.2 bounds the balance
    // heuristic's; the power heuristic does better in practice, his §9.2.3).
    const double exponents[] = {5.0, 200.0};
    // Four spots on the plate, seen from a camera in front: each region is one camera ray.
    const Vec3 eye(0.0, 1.0, 3.0);
    const Vec3 spots[] = {Vec3(-1.0, 0.0, 0.0), Vec3(1.5, 0.0, 0.0), Vec3(-0.5, 0.0, -0.5),
                          Vec3(1.0, 0.0, 1.0)};
    const int tests = 2 * 4 * 2;
    for (const double n : exponents) {
        GIVEN("the plate of Phong exponent " + std::to_string(n)) {
            rbtest::TestWorld mis, light, bsdf;
            veachScene(mis, n, "mis");
            veachScene(light, n, "light");
            veachScene(bsdf, n, "bsdf");
            THEN(
                "at each of four spots the three means agree within the z-bound, and MIS's "
                "variance is at most 1.1 times the better technique's") {
                for (const Vec3& spot : spots) {
                    const rb::Ray ray{eye, spot - eye};
                    const int paths = 40000;
                    auto run = [&](const rbtest::TestWorld& w) {
                        double sum = 0.0, sum2 = 0.0;
                        for (int i = 0; i < paths; ++i) {
                            const double x = pathSample(w, ray, i);
                            sum += x;
                            sum2 += x * x;
                        }
                        const double mean = sum / paths;
                        return std::make_pair(mean, (sum2 - paths * mean * mean) / (paths - 1));
                    };
                    const auto [mMis, vMis] = run(mis);
                    const auto [mLight, vLight] = run(light);
                    const auto [mBsdf, vBsdf] = run(bsdf);
                    INFO("spot " << spot.x << ", " << spot.z << ": means MIS " << mMis << " light "
                                 << mLight << " BSDF " << mBsdf << "; variances " << vMis << ", "
                                 << vLight << ", " << vBsdf);
                    const double z = rbtest::zCritical(rb::sidak(0.01, tests));
                    CHECK(std::abs(mMis - mLight) <= z * std::sqrt((vMis + vLight) / paths));
                    CHECK(std::abs(mMis - mBsdf) <= z * std::sqrt((vMis + vBsdf) / paths));
                    CHECK(vMis <= 1.1 * std::min(vLight, vBsdf));
                }
            }
        }
    }
}

SCENARIO("Russian roulette changes the variance, not the mean", "[ch18][ex18.1][ex18.3][ex18.4]") {
    // Source: a path that goes on with probability q and then carries 1/q more has the same
    // expected value (pbrt-v4 §14.5.2); with the same depth limit, roulette and no roulette
    // estimate exactly the same quantity.
    GIVEN("the furnace of albedo 0.7 emitting 0.5, with paths of at most 40 bounces") {
        auto world = [](const std::string& roulette) {
            auto w = std::make_unique<rbtest::TestWorld>();
            rb::Material wall;
            wall.kd = Colour(0.7);
            wall.emission = Colour(0.5);
            w->addSphere(rb::Mat4(1.0), w->material(wall));
            w->build(rbtest::chapters(18), -1,
                     pathOptions({{"path-depth", "40"}, {"path-roulette", roulette}}));
            runPrePasses(*w);
            return w;
        };
        const auto withRoulette = world("1");
        const auto without = world("1000");
        WHEN("the same directions are traced with roulette from the first bounce, and without") {
            const auto [m1, e1] = fromCentre(*withRoulette, 20000);
            const auto [m2, e2] = fromCentre(*without, 20000);
            THEN("the means agree within the z-bound, and roulette's variance is larger") {
                INFO("with roulette " << m1 << " ± " << e1 << ", without " << m2 << " ± " << e2);
                CHECK(std::abs(m1 - m2) <= rbtest::zCritical(0.01) * std::hypot(e1, e2));
                CHECK(e1 > e2);
            }
        }
    }
}

SCENARIO("Where a scene has no indirect light, path tracing equals Whitted's direct light",
         "[ch18][ex18.3]") {
    // Source: a lone diffuse ball under a point light, on black, with no ambient term: the
    // only light is the direct light, kd I cos θ / r² in A4's units (chapter 2), which the
    // path tracer's next-event estimate computes with the physical kd/π times the π of A4's
    // lights. Every bounce leaves for the black background.
    GIVEN("a diffuse ball of kd 0.7 lit by a point light, no ambient") {
        const std::string lua = R"(
local root = gr.node('root')
local s = gr.sphere('s')
s:set_material(gr.material({0.7, 0.5, 0.3}, {0, 0, 0}, 1))
root:add_child(s)
gr.render(root, 'x.png', 24, 24, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 40, {0, 0, 0},
          {gr.light({2, 3, 4}, {0.9, 0.8, 0.7}, {1, 0, 0})})
)";
        const auto whitted = rbtest::worldFromLua(lua, rbtest::chapters(18));
        const auto path = rbtest::worldFromLua(lua, rbtest::chapters(18), {{"integrator", "path"}});
        WHEN("both render it") {
            rb::RayCounters counters;
            const rb::Image a = rbtest::renderSmall(*whitted, 24, 24, counters);
            const rb::Image b = rbtest::renderSmall(*path, 24, 24, counters);
            THEN("every pixel agrees to rounding") {
                double worst = 0.0;
                for (size_t i = 0; i < a.data().size(); ++i)
                    worst = std::max(worst, std::abs(double(a.data()[i]) - b.data()[i]));
                INFO("largest difference " << worst);
                CHECK(worst < 1e-6);
            }
        }
    }
}

SCENARIO(
    "The normalized Phong lobe reflects all of the light at normal incidence and never "
    "more than arrives",
    "[ch18][ex18.2]") {
    // Source: with wo along n, the lobe's axis is n, and ∫ (s+2)/(2π) cos^s α cos θ dω =
    // (s+2)/(2π) · 2π/(s+2) = 1 (Lafortune and Willems 1994); at oblique incidence part of the
    // lobe falls below the horizon, so the albedo is less. Integrated numerically about the
    // lobe's axis by the sampling lab's adaptive Simpson cubature.
    const double exponents[] = {0.0, 1.0, 5.0, 20.0, 100.0, 1000.0};
    for (const double s : exponents)
        for (const double degrees : {0.0, 30.0, 60.0, 85.0}) {
            GIVEN("exponent " + std::to_string(s) + " at " + std::to_string(degrees) + "°") {
                const double theta = degrees * kPi / 180.0;
                const Vec3 n(0.0, 0.0, 1.0), wo(std::sin(theta), 0.0, std::cos(theta));
                const Vec3 axis = 2.0 * glm::dot(n, wo) * n - wo;
                // A frame about the lobe's axis: (φ, cos α) to a direction.
                const Vec3 t1 = glm::normalize(glm::cross(axis, Vec3(0.0, 1.0, 0.0)));
                const Vec3 t2 = glm::cross(axis, t1);
                auto integrand = [&](const rb::Vec2& q) {
                    const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - q.y * q.y));
                    const Vec3 wi =
                        sinAlpha * std::cos(q.x) * t1 + sinAlpha * std::sin(q.x) * t2 + q.y * axis;
                    const double cosTheta = glm::dot(wi, n);
                    return cosTheta > 0.0 ? rb::normalizedPhong(s, n, wo, wi) * cosTheta : 0.0;
                };
                const double albedo = rb::integrate2D(integrand, 0.0, 2.0 * kPi, 0.0, 1.0);
                THEN("its albedo is 1 at normal incidence and at most 1 otherwise") {
                    INFO("albedo " << albedo);
                    if (degrees == 0.0)
                        CHECK(albedo == Approx(1.0).epsilon(1e-4));
                    else
                        CHECK(albedo <= 1.0 + 1e-4);
                    CHECK(albedo > 0.0);
                }
            }
        }
}

SCENARIO("A material that would reflect more than it receives is scaled down", "[ch18]") {
    GIVEN("kd 0.8 and ks 0.5 with a mirror of 0.2: 1.5 in all") {
        rb::Material m;
        m.kd = Colour(0.8, 0.6, 0.4);
        m.ks = Colour(0.5);
        m.params["reflect"] = 0.2;
        const rb::Shares s = rb::materialShares(m, true, false);
        THEN("every channel's total is at most 1, in the same proportions") {
            CHECK(s.scale == Approx(1.5));
            CHECK(s.kd.r + s.ks.r + s.mirror == Approx(1.0));
            CHECK(s.kd.b / s.kd.r == Approx(0.5));
        }
    }
}

SCENARIO("The path tracer's samplers draw the densities MIS weighs them by",
         "[ch18][ex18.2][ex18.3]") {
    // Source: Pearson's chi-square test at α = 0.01 over the sampling lab's bins (bins
    // expecting fewer than 5 pooled), Šidák-corrected for the runs below.
    const std::vector<rb::Warp> warps = rb::builtWarps(rbtest::chapters(18).built());
    auto find = [&](const std::string& name) {
        for (const rb::Warp& w : warps)
            if (w.name == name) return w;
        FAIL("no warp " << name);
        return rb::Warp{};
    };
    const std::vector<std::pair<std::string, std::map<std::string, double>>> runs = {
        {"path-bsdf", {}},
        {"path-bsdf", {{"kd", 1.0}, {"ks", 0.0}}},
        {"path-bsdf", {{"kd", 0.0}, {"ks", 1.0}, {"exponent", 200.0}, {"angle", 10.0}}},
        {"path-bsdf", {{"kd", 0.2}, {"ks", 0.8}, {"exponent", 3.0}, {"angle", 75.0}}},
        {"path-light", {}},
        {"path-light", {{"height", 0.2}, {"offset", 2.0}}}};
    for (const auto& [name, values] : runs) {
        rb::WarpRunSettings settings;
        settings.samples = 200000;
        settings.seed = seed();
        const rb::WarpRun run = rb::runWarp(find(name), values, settings);
        INFO(name << " " << run.caption << ": p = " << run.test.pValue << "; "
                  << rbtest::warptestHint(name));
        CHECK(run.test.pValue > rb::sidak(0.01, static_cast<int>(runs.size())));
    }
}

namespace {

/// A small Cornell box lit by its ceiling, path traced: for determinism and cost tests.
std::string smallBox() {
    return R"(
gr.integrator('path')
local white = gr.material{kd = {0.7, 0.7, 0.7}}
local red = gr.material{kd = {0.6, 0.1, 0.1}}
local lamp = gr.material{kd = {0, 0, 0}, emission = {8, 8, 8}}
local root = gr.node('root')
local function slab(m, sx, sy, sz, x, y, z)
  local s = gr.cube('s'); s:scale(sx, sy, sz); s:translate(x, y, z); s:set_material(m)
  root:add_child(s)
end
slab(white, 2.2, 0.1, 2.2, -1.1, -1.1, -1.1)
slab(white, 2.2, 0.1, 2.2, -1.1, 1.0, -1.1)
slab(white, 2.2, 2.2, 0.1, -1.1, -1.1, -1.1)
slab(red, 0.1, 2.2, 2.2, -1.1, -1.1, -1.1)
slab(lamp, 0.6, 0.02, 0.6, -0.3, 0.98, -0.3)
gr.render(root, 'x.png', 16, 16, {0, 0, 3.5}, {0, 0, -1}, {0, 1, 0}, 40, {0, 0, 0}, {})
)";
}

}  // namespace

SCENARIO("Path-traced renders are the same bits on one thread and two",
         "[ch18][ex18.1][ex18.3][ex18.4]") {
    GIVEN("a small box lit by its ceiling") {
        const auto world = rbtest::worldFromLua(smallBox(), rbtest::chapters(18));
        auto render = [&](int threads) {
            rb::RenderSettings settings;
            settings.threads = threads;
            settings.samplesPerPixel = 4;
            settings.seed = seed();
            settings.shouldStop = threads == 2 ? rbtest::bothThreadsTakeTiles() : nullptr;
            rb::RayCounters counters;
            return rbtest::renderAt(*world, 16, 16, settings, counters);
        };
        THEN("the images are bit-identical, and lit") {
            const rb::Image one = render(1);
            CHECK(rbtest::bitIdentical(one, render(2)));
            CHECK(rbtest::allFiniteNonNegative(one));
            float brightest = 0.0f;
            for (float v : one.data()) brightest = std::max(brightest, v);
            CHECK(brightest > 0.1f);
        }
    }
}

SCENARIO("A scene that does not ask for path tracing pays nothing for chapter 18", "[ch18]") {
    GIVEN("chapter 17's scene, which neither emits nor asks for paths") {
        const auto world = rbtest::worldFromLua(
            rbtest::oneMaterialScene("gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)"),
            rbtest::chapters(18));
        const auto before = rbtest::worldFromLua(
            rbtest::oneMaterialScene("gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)"),
            rbtest::chapters(17));
        THEN("no estimator, pre-pass or shading term is installed") {
            CHECK(world->pipeline.radiance == nullptr);
            CHECK(world->pipeline.prePasses.size() == before->pipeline.prePasses.size());
            CHECK(world->pipeline.terms.size() == before->pipeline.terms.size());
        }
    }
    GIVEN("an emitting ball rendered by Whitted's integrator") {
        const auto world = rbtest::worldFromLua(
            rbtest::oneMaterialScene("gr.material{kd = {0, 0, 0}, emission = {0.25, 0.5, 0.75}}"),
            rbtest::chapters(18));
        THEN("it glows with its emission, and lights nothing") {
            const Colour c = rbtest::traceOne(*world, rb::Ray{Vec3(0, 0, 10), Vec3(0, 0, -1)});
            INFO(c.r << " " << c.g << " " << c.b);
            CHECK(c.g == Approx(0.5));
            CHECK(world->pipeline.radiance == nullptr);
        }
    }
}

SCENARIO("Bad path-tracing input is refused with the call and what was expected", "[ch18]") {
    auto error = [](const std::string& call) {
        return rbtest::loadError(
            call + "\n" + rbtest::oneMaterialScene("gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)"),
            rbtest::chapters(18));
    };
    THEN("each names the call and the field") {
        CHECK_THAT(error("gr.integrator('bidirectional')"),
                   Contains("gr.integrator: method must be 'path' or 'whitted'"));
        CHECK_THAT(error("gr.integrator{method = 'path', max_depth = 0}"), Contains("max_depth"));
        CHECK_THAT(error("gr.integrator{methd = 'path'}"), Contains("unknown field 'methd'"));
        CHECK_THAT(error("gr.integrator(1, 2)"), Contains("gr.integrator expects"));
        CHECK_THAT(error("gr.material{emission = {1, -1, 0}}"), Contains("emission"));
        CHECK_THAT(error("gr.material{emission = {1, 0/0, 0}}"), Contains("emission"));
        CHECK_THAT(error("gr.material{emission = 2}"), Contains("emission"));
    }
    THEN("an A4 scene still needs a light, and a path-traced one may do without") {
        const std::string noLight = R"(
local root = gr.node('root')
local s = gr.sphere('s')
root:add_child(s)
gr.render(root, 'x.png', 8, 8, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 40, {0, 0, 0}, {})
)";
        CHECK_THAT(rbtest::loadError(noLight, rbtest::chapters(18)),
                   Contains("at least one light"));
        CHECK(rbtest::loadError("gr.integrator('path')\n" + noLight, rbtest::chapters(18)).empty());
    }
    THEN("the command line's values are checked") {
        const std::string lua = smallBox();
        CHECK_THROWS_WITH(rbtest::worldFromLua(lua, rbtest::chapters(18), {{"integrator", "bdpt"}}),
                          Contains("--integrator: expected 'path' or 'whitted'"));
        CHECK_THROWS_WITH(rbtest::worldFromLua(lua, rbtest::chapters(18), {{"path-depth", "0"}}),
                          Contains("--path-depth"));
        CHECK_THROWS_WITH(
            rbtest::worldFromLua(lua, rbtest::chapters(18), {{"path-strategy", "both"}}),
            Contains("--path-strategy"));
    }
}
