/// \file
/// Tests of the sampling lab (src/lab/, rt's `--warptest` option), which every chapter binary
/// holds.
///
/// The lab claims to tell a sampler that draws the density its code states from one that does
/// not: it bins the points, integrates the stated pdf over every bin, and runs the chi-square
/// test the chapter tests use (src/lab/chi_square.h). These tests feed it samplers written
/// here, independent of any chapter's exercise code: a uniform point on the disk (Source:
/// r = √u has P(r ≤ ρ) = ρ², the area fraction) must pass; the classic mistake r = u, which
/// crowds the centre, must fail by far; so must points where the pdf is zero, and a sampler
/// that draws nothing. The cubature that turns a pdf into expected counts is checked against
/// closed forms, and the command line against bad input. Seed 1 throughout.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "app/options.h"
#include "lab/chi_square.h"
#include "lab/warp_test.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Vec2;

namespace {

/// A sampler of the unit disk, r = radius(u1), binned on [-1, 1]², stated pdf 1/π inside.
rb::Warp diskWarp(double (*radius)(double)) {
    rb::Warp w;
    w.name = "test-disk";
    w.chapter = 1;
    w.title = "a test disk";
    w.setup = [radius](const std::map<std::string, double>&) {
        rb::WarpSetup s;
        s.domain = {-1.0, 1.0, -1.0, 1.0, "x", "y"};
        s.caption = "test";
        s.draw = [radius](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            for (std::uint64_t i = 0; i < count; ++i) {
                rb::Sampler sampler(seed, 0, i);
                const Vec2 u = sampler.next2D();
                const double r = radius(u.x), phi = 2.0 * M_PI * u.y;
                points.push_back({r * std::cos(phi), r * std::sin(phi)});
            }
        };
        s.pdf = [](const Vec2& p) { return glm::dot(p, p) <= 1.0 ? 1.0 / M_PI : 0.0; };
        return s;
    };
    return w;
}

rb::WarpRun runOnce(const rb::Warp& warp) {
    rb::WarpRunSettings settings;
    settings.samples = 100000;
    settings.seed = 1;
    return rb::runWarp(warp, {}, settings);
}

}  // namespace

SCENARIO("the sampling lab passes a sampler that draws its pdf and fails one that does not",
         "[ch01][lab]") {
    GIVEN("a uniform point on the unit disk, r = √u, and its pdf 1/π") {
        const rb::WarpRun run = runOnce(diskWarp([](double u) { return std::sqrt(u); }));
        THEN("the chi-square test does not reject it at α = 0.01") {
            INFO("chi-square " << run.test.statistic << ", dof " << run.test.dof);
            CHECK(run.samples == 100000);
            CHECK(run.test.pValue > 0.01);
        }
    }
    GIVEN("the classic mistake r = u, which crowds the centre, with the same stated pdf") {
        const rb::WarpRun run = runOnce(diskWarp([](double u) { return u; }));
        THEN("the lab rejects it with p far below 0.01") {
            CHECK(run.test.pValue < 1e-12);
        }
    }
    GIVEN("a sampler whose points leave the disk its pdf states (r = 2u)") {
        const rb::WarpRun run = runOnce(diskWarp([](double u) { return 2.0 * std::sqrt(u); }));
        THEN("points where the pdf is 0 fail it outright") {
            CHECK(run.outsideObserved > 0);
            CHECK(run.test.pValue == 0.0);
        }
    }
    GIVEN("a sampler that draws no points at all (a blank exercise)") {
        rb::Warp warp = diskWarp([](double u) { return u; });
        const auto setup = warp.setup;
        warp.setup = [setup](const std::map<std::string, double>& v) {
            rb::WarpSetup s = setup(v);
            s.draw = [](std::uint64_t, std::uint64_t, std::vector<Vec2>&) {};
            return s;
        };
        const rb::WarpRun run = runOnce(warp);
        THEN("it fails") {
            CHECK(run.samples == 0);
            CHECK(run.test.pValue == 0.0);
        }
    }
}

SCENARIO("the lab's cubature integrates a pdf over a bin", "[ch01][lab]") {
    GIVEN("a polynomial, x²y on [0, 1]²") {
        THEN("Simpson's rule is exact: 1/6") {
            // Source: ∫₀¹ x² dx · ∫₀¹ y dy = 1/3 · 1/2.
            CHECK(rb::integrate2D([](const Vec2& p) { return p.x * p.x * p.y; }, 0, 1, 0, 1) ==
                  Approx(1.0 / 6.0).epsilon(1e-12));
        }
    }
    GIVEN("the uniform density on the unit disk, 1/π inside and 0 outside, which jumps") {
        const auto pdf = [](const Vec2& p) { return glm::dot(p, p) <= 1.0 ? 1.0 / M_PI : 0.0; };
        THEN("over the square [-1, 1]² it integrates to 1, and over [0, 1]² to 1/4") {
            // Source: the disk's area is π; a quadrant holds a quarter of it.
            CHECK(rb::integrate2D(pdf, -1, 1, -1, 1) == Approx(1.0).margin(1e-4));
            CHECK(rb::integrate2D(pdf, 0, 1, 0, 1) == Approx(0.25).margin(1e-4));
        }
    }
}

/// A build whose one sampler is the test disk with a parameter, for the command line's tests.
std::vector<rb::Warp> testWarps() {
    rb::Warp w = diskWarp([](double u) { return std::sqrt(u); });
    w.parameters = {{"scale", 1.0, 0.5, 2.0, "unused"}};
    return {w};
}

SCENARIO("./rt --warptest refuses bad input with a message and exit code 1", "[ch01][lab]") {
    rb::Feature feature{"lab_test", 1, "the lab's test sampler", false, nullptr, nullptr};
    feature.warps = testWarps;
    const auto command = [&](const std::vector<std::string>& args, std::string& err) {
        std::ostringstream out, errors;
        const int code = rb::warpTestCommand(args, {feature}, out, errors);
        err = errors.str();
        return code;
    };
    std::string err;
    WHEN("the sampler's name is unknown") {
        THEN("it exits 1 and lists the samplers of the build") {
            CHECK(command({"test"}, err) == 1);
            CHECK_THAT(err, Contains("no sampler named 'test'"));
            CHECK_THAT(err, Contains("test-disk"));
        }
    }
    WHEN("a parameter is unknown, out of range or not a number, or an option is malformed") {
        THEN("each exits 1 and says which") {
            CHECK(command({"test-disk", "size=3"}, err) == 1);
            CHECK_THAT(err, Contains("no parameter 'size'; it has: scale"));
            CHECK(command({"test-disk", "scale=3"}, err) == 1);
            CHECK_THAT(err, Contains("scale must be from 0.5 to 2, got 3"));
            CHECK(command({"test-disk", "scale=big"}, err) == 1);
            CHECK_THAT(err, Contains("must be a number"));
            CHECK(command({"test-disk", "--bins", "12"}, err) == 1);
            CHECK_THAT(err, Contains("expected XxY"));
            CHECK(command({"test-disk", "--output", "figure.png"}, err) == 1);
            CHECK_THAT(err, Contains("name a .svg file"));
            CHECK(command({"test-disk", "--colour", "red"}, err) == 1);
            CHECK_THAT(err, Contains("unknown option --colour"));
        }
    }
    WHEN("--warptest comes after another option") {
        THEN("the renderer's command line refuses it and says it must come first") {
            const char* argv[] = {"rt", "--quiet", "--warptest", "phong-lobe"};
            CHECK_THROWS_WITH(rb::parseCommandLine(4, argv),
                              Contains("--warptest must come first"));
        }
    }
    WHEN("no sampler is named") {
        THEN("it exits 1 with the usage and the list") {
            CHECK(command({}, err) == 1);
            CHECK_THAT(err, Contains("usage: ./rt --warptest NAME"));
            CHECK_THAT(err, Contains("test-disk"));
        }
    }
}
