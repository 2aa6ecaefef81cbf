/// \file
/// Chapter 13 tests: depth of field.
///
/// Chapter 13 claims that a thin lens in place of the pinhole keeps one plane sharp and blurs
/// every other depth by the thin-lens circle of confusion, and that its samples can share a
/// pixel's rays with chapter 8's pixel samples instead of multiplying them. The tests prove the
/// geometry on rays, where it is exact: every lens sample through one image position meets the
/// others on the focal plane, at the pinhole ray's point; the rays through one image position
/// spread, at another depth, over a disk (or square) whose diameter is the thin-lens formula's;
/// a lens of aperture 0 gives the pinhole's rays and images bit for bit. The lens sampler is
/// tested as a Monte Carlo routine: the concentric map and the stratified pairing put points
/// uniformly on the disk (chi-square over equal-area cells, pooled below 5, α = 0.01 shared by
/// the three tests with Šidák's correction; a fixed seed 1, RB_CH13_SEED re-runs them on other
/// streams, checked locally for seeds 1 to 10), each ray of a pixel gets its own lens stratum,
/// and stratification lowers the error of a blurred edge. End-to-end: the rays per pixel are
/// the larger of the pixel's and the lens's counts, images are the same on 1 and 2 threads,
/// the settings come from the command line, gr.lens, gr.option and seed 001's gr.render, and
/// extreme lenses give finite, non-negative images.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/render_warnings.h"
#include "core/camera_rays.h"
#include "core/error.h"
#include "dof/dof.h"
#include "dof/lens_sampling.h"
#include "dof/thin_lens.h"
#include "lab/chi_square.h"
#include "test_helpers.h"
#include "test_messages.h"

using Catch::Contains;
using rb::Vec2;
using rb::Vec3;

namespace {

/// The seed of every random stream in this file: 1, or RB_CH13_SEED.
std::uint64_t seed() {
    return rbtest::seedFromEnv("RB_CH13_SEED");
}

/// A camera that looks down and to the side, so the lens plane is not axis-aligned.
rb::PinholeCamera tiltedCamera(int width = 64, int height = 48) {
    rb::CameraSpec spec;
    spec.eye = Vec3(1.0, 2.0, 6.0);
    spec.view = Vec3(-0.3, -0.4, -1.0);
    spec.up = Vec3(0.1, 1.0, 0.0);
    spec.fovyDegrees = 40.0;
    return rb::PinholeCamera(spec, width, height);
}

/// The point where a ray reaches depth `depth` along the camera's view (distance from the eye's
/// plane perpendicular to the view).
Vec3 atDepth(const rb::PinholeCamera& camera, const rb::Ray& ray, double depth) {
    const double t = (depth - glm::dot(ray.o - camera.eye(), camera.forward())) /
                     glm::dot(ray.d, camera.forward());
    return ray.o + t * ray.d;
}

/// The rings and sectors of the disk's equal-area cells.
constexpr int kRings = 10, kSectors = 16;

/// The equal-area cell of a point of the unit disk: ring k holds r² in [k/10, (k+1)/10).
int diskCell(const Vec2& p) {
    const int ring = std::min(kRings - 1, static_cast<int>(glm::dot(p, p) * kRings));
    double phi = std::atan2(p.y, p.x);
    if (phi < 0.0) phi += 2.0 * glm::pi<double>();
    const int sector =
        std::min(kSectors - 1, static_cast<int>(phi / (2.0 * glm::pi<double>()) * kSectors));
    return ring * kSectors + sector;
}

/// The p-value of the chi-square test of `points` against the uniform density on the unit
/// disk (concentricDiskPdf), over kRings × kSectors equal-area cells; cells expecting fewer
/// than 5 are pooled. A point outside the disk fails the test outright.
double diskChiSquareP(const std::vector<Vec2>& points) {
    std::vector<double> observed(kRings * kSectors, 0.0);
    for (const Vec2& p : points) {
        if (rb::concentricDiskPdf(p) == 0.0) return 0.0;
        observed[diskCell(p)] += 1.0;
    }
    // Each cell has area π / (rings · sectors); the pdf is 1/π: expected N / cells.
    const double expected = points.size() / static_cast<double>(observed.size());
    REQUIRE(expected >= 5.0);  // no pooling needed at these counts
    return rb::chiSquareTest(observed, std::vector<double>(observed.size(), expected)).pValue;
}

/// Šidák's per-test level for the three chi-square tests at family-wise α = 0.01.
/// Source: Šidák, JASA 62 (1967): 1 − (1 − α)^(1/k).
const double kPerTestAlpha = rb::sidak(0.01, 3);

/// A lens with the given aperture, focus, samples and shape.
rb::ThinLens lens(double aperture, double focus, int samples = 16,
                  rb::ApertureShape shape = rb::ApertureShape::Disk) {
    return rb::ThinLens({aperture, focus, samples, shape});
}

/// Three balls at depths 4, 8 and 16 on a floor, a Phong scene with no random shading.
const std::string kBalls =
    "local m = gr.material({0.8, 0.3, 0.2}, {0.5, 0.5, 0.5}, 30)\n"
    "local g = gr.material({0.3, 0.7, 0.3}, {0.2, 0.2, 0.2}, 10)\n"
    "root = gr.node('root')\n"
    "for i, z in ipairs({4, 8, 16}) do\n"
    "  local s = gr.nh_sphere('s' .. i, {i - 2, 0, 8 - z}, 0.7)\n"
    "  s:set_material(m)\n"
    "  root:add_child(s)\n"
    "end\n"
    "local floor = gr.cube('floor')\n"
    "floor:scale(20, 0.1, 40)\n"
    "floor:translate(-10, -0.8, -30)\n"
    "floor:set_material(g)\n"
    "root:add_child(floor)\n";

/// The render line of kBalls: the eye at z = 8, view = (0, 0, -8): the target at depth 8.
const std::string kBallsRender =
    "gr.render(root, 'out.png', 40, 30, {0, 0, 8}, {0, 0, -8}, {0, 1, 0}, 50, {0.2, 0.2, 0.2},"
    " {gr.light({-4, 6, 10}, {0.9, 0.9, 0.9}, {1, 0, 0})}";

/// The world of `lua` built with chapters 1–13 (`spec`) and command-line options `cli`.
std::unique_ptr<rb::World> world(const std::string& lua,
                                 const std::map<std::string, std::string>& cli = {},
                                 const std::string& spec = "all") {
    return rbtest::worldFromLua(lua, rbtest::chapters(13, spec), cli);
}

/// The thin lens a world installed, or null.
const rb::ThinLens* installed(const rb::World& w) {
    return dynamic_cast<const rb::ThinLens*>(w.pipeline.cameraRays.get());
}

/// The lens position of ray s of n² rays through one image position: a uniform point in cell s
/// of an n × n grid over the unit square (the test's own stratification, so that the thin-lens
/// ray is checked before exercise 13.3's pairing is written).
Vec2 lensCell(int s, int n, rb::Sampler& sampler) {
    const Vec2 xi = sampler.next2D();
    return {((s % n) + xi.x) / n, ((s / n) + xi.y) / n};
}

/// The outcome of a chi-square test, in words for a failure message.
std::string uniformity(const std::string& what, double p) {
    std::ostringstream out;
    out << "expected " << what << " to be uniform: the chi-square test gives p = " << p
        << ", below the level " << kPerTestAlpha << ", which a uniform density falls under in "
        << "only 1 run in " << static_cast<int>(1.0 / kPerTestAlpha);
    return out.str();
}

}  // namespace

// [ch13-focal-plane]
namespace {

/// Every ray of a lens through four image positions of the tilted camera, 64 lens positions
/// each (one per cell of an 8 × 8 grid), reaches depth 7 at the pinhole ray's point and starts
/// from 64 different lens points.
void checkFocalPlane(rb::ApertureShape shape) {
    const rb::PinholeCamera camera = tiltedCamera();
    const rb::ThinLens thin = lens(0.8, 7.0, 64, shape);
    int missed = 0, pinholeMissed = 0, distinctOrigins = 0, positions = 0;
    for (const Vec2 film : {Vec2(0.5, 0.5), Vec2(32.0, 24.0), Vec2(63.7, 2.2), Vec2(5.0, 47.9)}) {
        const Vec3 focus = rb::focalPlanePoint(camera, film, 7.0);
        const rb::Ray pinhole = camera.generateRay(film.x, film.y);
        pinholeMissed += glm::length(atDepth(camera, pinhole, 7.0) - focus) > 1e-12 * 7;
        std::set<std::pair<double, double>> origins;
        for (int s = 0; s < 64; ++s) {
            rb::Sampler sampler(seed(), 5, s);
            const rb::Ray ray = thin.rayThrough(camera, film, lensCell(s, 8, sampler));
            origins.insert({ray.o.x, ray.o.y});
            missed += glm::length(atDepth(camera, ray, 7.0) - focus) > 1e-12 * 7.0;
        }
        distinctOrigins += origins.size() == 64;
        ++positions;
    }
    // Source: a thin lens focuses every ray from a point of the focal plane to one image
    // point (Gauss); the construction aims each ray at that point.
    INFO("expected every ray to reach depth 7 at the pinhole ray's point there (eye + 7·d): "
         << missed << " of " << 64 * positions << " lens rays miss it by more than 7e-12");
    CHECK(pinholeMissed == 0);
    CHECK(missed == 0);
    INFO("expected 64 different ray origins on the lens for each image position: "
         << distinctOrigins << " of " << positions << " positions have them");
    CHECK(distinctOrigins == positions);
}

}  // namespace

SCENARIO("every lens ray through one image position meets the others on the focal plane: square",
         "[ch13][ex13.1]") {
    GIVEN("a tilted camera and a thin lens with a square aperture, focused at 7 units") {
        WHEN("64 lens positions go through each of several image positions") {
            THEN(
                "every ray reaches depth 7 at the pinhole ray's point, within rounding, "
                "from 64 different points of the lens") {
                checkFocalPlane(rb::ApertureShape::Square);
            }
        }
    }
}

SCENARIO("every lens ray through one image position meets the others on the focal plane: disk",
         "[ch13][ex13.1][ex13.2]") {
    GIVEN("a tilted camera and a thin lens with a disk aperture, focused at 7 units") {
        WHEN("64 lens positions go through each of several image positions") {
            THEN(
                "every ray reaches depth 7 at the pinhole ray's point, within rounding, "
                "from 64 different points of the lens") {
                checkFocalPlane(rb::ApertureShape::Disk);
            }
        }
    }
}
// [ch13-focal-plane]

// [ch13-blur-circle]
namespace {

/// How lens rays through the image centre spread at one depth, seen from the eye.
struct Spread {
    double reach;       ///< the farthest ray's distance (for a square, its larger coordinate)
    double meanSquare;  ///< the mean squared distance
};

/// The spread at depth S2 of 4096 rays of `thin` through the image centre of the tilted camera,
/// one per cell of a 64 × 64 grid of lens positions, around the pinhole ray's point.
Spread spreadAt(const rb::ThinLens& thin, double S2) {
    const rb::PinholeCamera camera = tiltedCamera();
    const Vec2 centre(32.0, 24.0);
    const bool disk = thin.settings().shape == rb::ApertureShape::Disk;
    // The rays meet the plane at S2 around the pinhole ray's point; seen from the eye, their
    // spread on the image plane is (spread in the world) / S2.
    const Vec3 middle = atDepth(camera, camera.generateRay(centre.x, centre.y), S2);
    Spread spread{0.0, 0.0};
    for (int s = 0; s < 4096; ++s) {
        rb::Sampler sampler(seed(), 7, s);
        const rb::Ray ray = thin.rayThrough(camera, centre, lensCell(s, 64, sampler));
        const Vec3 q = atDepth(camera, ray, S2) - middle;
        const Vec2 image(glm::dot(q, camera.right()) / S2, glm::dot(q, camera.upVector()) / S2);
        spread.reach =
            std::max(spread.reach,
                     disk ? glm::length(image) : std::max(std::abs(image.x), std::abs(image.y)));
        spread.meanSquare += glm::dot(image, image) / 4096;
    }
    return spread;
}

/// The aperture A = 0.5, the focus S1 = 8 and the depths S2 of the blur-circle tests.
constexpr double kBlurA = 0.5, kBlurS1 = 8.0;
const double kBlurDepths[] = {3.0, 5.0, 12.0, 40.0};

}  // namespace

SCENARIO("the rays through one image position spread over the thin-lens blur square",
         "[ch13][ex13.1]") {
    GIVEN("a square lens of aperture A = 0.5 focused at S1 = 8, and points at S2 = 3, 5, 12, 40") {
        WHEN("4096 stratified lens rays through the image centre reach each depth S2") {
            THEN("they spread over the thin-lens square of each depth, uniformly") {
                const rb::ThinLens thin = lens(kBlurA, kBlurS1, 4096, rb::ApertureShape::Square);
                for (const double S2 : kBlurDepths) {
                    // Source: the thin lens of focal length F focuses S1 at v = F·S1/(S1 − F)
                    // (the lens equation 1/F = 1/S1 + 1/v); a point at S2 blurs into a circle
                    // of diameter c = A·v·|S2 − S1| / (S1·S2) on that sensor. Scaled by 1/v to
                    // the image plane at distance 1: c/v = A·|S2 − S1| / (S1·S2), for any F
                    // (here F = 0.05, to show it drops out).
                    const double F = 0.05, v = F * kBlurS1 / (kBlurS1 - F);
                    const double c = kBlurA * v * std::abs(S2 - kBlurS1) / (kBlurS1 * S2);
                    const double expected = c / v;
                    CHECK(rb::blurCircleDiameter(kBlurA, kBlurS1, S2) ==
                          Approx(expected).epsilon(1e-12));
                    const Spread square = spreadAt(thin, S2);
                    const double h = 0.5 * expected;
                    INFO("depth " << S2 << ": the farthest ray reaches " << square.reach
                                  << " and the mean squared distance is " << square.meanSquare
                                  << "; expected a square of half side A·|S2 − S1|/(2·S1·S2) = "
                                  << h << " seen from the eye, the farthest reaching its edge "
                                  << "and none beyond, and the mean squared distance 2h²/3 = "
                                  << 2.0 / 3.0 * h * h);
                    // The farthest ray lies on the square's edge, none beyond: with 64 × 64
                    // strata the outermost cells reach within 2/64 of it.
                    CHECK(square.reach <= h * (1.0 + 1e-9));
                    CHECK(square.reach >= h * (1.0 - 2.0 / 64.0));
                    // Source: x² + y² averages 2/3 over [-1,1]².
                    CHECK(square.meanSquare == Approx(2.0 / 3.0 * h * h).epsilon(0.01));
                }
            }
        }
    }
}

SCENARIO("the rays through one image position spread over the thin-lens blur circle",
         "[ch13][ex13.1][ex13.2]") {
    GIVEN("a disk lens of aperture A = 0.5 focused at S1 = 8, and points at S2 = 3, 5, 12, 40") {
        WHEN("4096 stratified lens rays through the image centre reach each depth S2") {
            THEN("they spread over the circle inscribed in the square lens's blur, uniformly") {
                // Measured against the square aperture's rays through the same lens, so that a
                // wrong lens size shows in the thin-lens ray's own row (13.1), not here.
                const rb::ThinLens disk = lens(kBlurA, kBlurS1, 4096, rb::ApertureShape::Disk);
                const rb::ThinLens square = lens(kBlurA, kBlurS1, 4096, rb::ApertureShape::Square);
                for (const double S2 : kBlurDepths) {
                    const Spread d = spreadAt(disk, S2), q = spreadAt(square, S2);
                    INFO("depth " << S2 << ": the disk's rays reach " << d.reach
                                  << ", mean squared distance " << d.meanSquare
                                  << "; expected them to reach as far as the square's (" << q.reach
                                  << ") within the last ring of strata, and 3/4 of "
                                  << "the square's mean squared distance (" << 0.75 * q.meanSquare
                                  << ")");
                    // The disk of radius R is inscribed in the square of half side R: the
                    // farthest rays of both reach R, within 2/64 with 64 × 64 strata.
                    CHECK(d.reach <= q.reach / (1.0 - 2.0 / 64.0));
                    CHECK(d.reach >= q.reach * (1.0 - 2.0 / 64.0));
                    // Source: ∫ r² dA / π over the unit disk = 1/2; x² + y² averages 2/3 over
                    // [-1,1]²: the ratio is 3/4.
                    CHECK(d.meanSquare / q.meanSquare == Approx(0.75).epsilon(0.01));
                }
            }
        }
    }
}
// [ch13-blur-circle]

// [ch13-pinhole]
SCENARIO("a lens of aperture 0 gives the pinhole camera's rays, bit for bit", "[ch13][ex13.1]") {
    GIVEN("a tilted camera and a lens of aperture 0 focused anywhere") {
        const rb::PinholeCamera camera = tiltedCamera();
        const rb::ThinLens thin = lens(0.0, 3.7, 16, rb::ApertureShape::Square);
        THEN("its rays through every pixel corner, for 16 lens positions, are the pinhole's") {
            int differing = 0;
            for (int y = 0; y <= 48; ++y)
                for (int x = 0; x <= 64; ++x)
                    for (int s = 0; s < 16; ++s) {
                        rb::Sampler sampler(seed(), y * 65 + x, s);
                        const rb::Ray a =
                            thin.rayThrough(camera, Vec2(x, y), lensCell(s, 4, sampler));
                        const rb::Ray b = camera.generateRay(x, y);
                        differing += std::memcmp(&a, &b, sizeof a) != 0;
                    }
            INFO("expected aperture 0 to give exactly the pinhole's rays: "
                 << differing << " of " << 65 * 49 * 16 << " rays differ in some bit");
            CHECK(differing == 0);
        }
    }
}

SCENARIO("a lens of aperture 0 renders the pinhole camera's image, bit for bit",
         "[ch13][ex13.1][ex13.2][ex13.3]") {
    GIVEN("the three-ball scene with jittered antialiasing (4 rays a pixel)") {
        const std::string lua =
            "gr.antialias{sampler = 'jittered', samples = 4}\n" + kBalls + kBallsRender + ")";
        const auto pinhole = world(lua, {}, "all,-dof");
        WHEN("a lens of aperture 0 is installed in its pipeline by hand") {
            auto withLens = world(lua, {}, "all,-dof");
            withLens->pipeline.cameraRays = std::make_shared<rb::ThinLens>(lens(0.0, 8.0, 4));
            THEN("the image is the pinhole's, bit for bit") {
                CHECK(rbtest::bitIdentical(rbtest::renderSmall(*pinhole, 40, 30),
                                           rbtest::renderSmall(*withLens, 40, 30)));
            }
        }
        WHEN("the scene asks for gr.lens{aperture = 0, samples = 16}") {
            const auto w = world("gr.lens{aperture = 0, samples = 16}\n" + lua);
            THEN("chapter 13 installs nothing, and the image is the pinhole's") {
                CHECK(installed(*w) == nullptr);
                CHECK(rbtest::bitIdentical(rbtest::renderSmall(*pinhole, 40, 30),
                                           rbtest::renderSmall(*w, 40, 30)));
            }
        }
    }
}
// [ch13-pinhole]

// [ch13-chi-square]
SCENARIO("the concentric map and the square aperture are uniform", "[ch13][ex13.2]") {
    GIVEN("the concentric map of the unit square onto the disk") {
        rbtest::Rng rng(seed());
        WHEN("it maps 64000 independent uniform points") {
            std::vector<Vec2> points;
            for (int i = 0; i < 64000; ++i) {
                const double u = rng.uniform();
                points.push_back(rb::concentricDisk(Vec2(u, rng.uniform())));
            }
            THEN("a chi-square test over 160 equal-area cells accepts the density 1/π") {
                const double p = diskChiSquareP(points);
                INFO(uniformity("the concentric map's points over the unit disk", p)
                     << "; " << rbtest::warptestHint("concentric-disk"));
                CHECK(p > kPerTestAlpha);
            }
        }
    }
    GIVEN("seed 001's square aperture") {
        rbtest::Rng rng(seed() + 1000);
        WHEN("it maps 64000 uniform points") {
            // Bin [-1,1]² into 16 × 16 equal cells: expected 250 each (pdf 1/4 × cell area 1/64).
            std::vector<double> observed(256, 0.0);
            bool inside = true;
            for (int i = 0; i < 64000; ++i) {
                const double u = rng.uniform();
                const Vec2 p = rb::squareAperture(Vec2(u, rng.uniform()));
                inside = inside && rb::squareAperturePdf(p) == 0.25;
                const int cx = std::min(15, static_cast<int>((p.x + 1.0) * 8.0));
                const int cy = std::min(15, static_cast<int>((p.y + 1.0) * 8.0));
                observed[cy * 16 + cx] += 1.0;
            }
            THEN("a chi-square test accepts the density 1/4") {
                const double p =
                    rb::chiSquareTest(observed, std::vector<double>(observed.size(), 250.0)).pValue;
                INFO(uniformity("the square aperture's points over [-1,1]²", p));
                CHECK(inside);
                CHECK(p > kPerTestAlpha);
            }
        }
    }
}

SCENARIO("the stratified, paired lens samples are uniform over the disk",
         "[ch13][ex13.2][ex13.3]") {
    GIVEN("the concentric map of the stratified lens samples of 4000 pixels, 16 rays each") {
        std::vector<Vec2> points;
        for (std::uint64_t pixel = 0; pixel < 4000; ++pixel)
            for (int s = 0; s < 16; ++s) {
                rb::Sampler sampler(seed(), pixel, s);
                points.push_back(
                    rb::concentricDisk(rb::stratifiedLensSample({seed(), pixel, s, 16}, sampler)));
            }
        THEN("they are uniform on the disk too (the pairing changes no density)") {
            const double p = diskChiSquareP(points);
            INFO(uniformity("the stratified lens samples over the unit disk", p)
                 << "; " << rbtest::warptestHint("thin-lens"));
            CHECK(p > kPerTestAlpha);
        }
    }
}
// [ch13-chi-square]

// [ch13-strata]
SCENARIO("each of a pixel's rays gets a lens stratum of its own", "[ch13][ex13.3]") {
    GIVEN("pixels with 1, 4, 7, 12, 16, 64 and 100 rays") {
        WHEN("20 pixels of each draw their rays' lens samples") {
            THEN("each ray has a cell of its own, in an order shuffled per pixel") {
                for (const int count : {1, 4, 7, 12, 16, 64, 100}) {
                    const int rows = rb::strataRows(count), cols = count / rows;
                    INFO(count << " rays: a grid of " << rows << " x " << cols);
                    CHECK(rows * cols == count);
                    CHECK(rows <= cols);
                    int filled = 0, shuffled = 0;
                    for (std::uint64_t pixel = 0; pixel < 20; ++pixel) {
                        std::set<int> cells;
                        bool identity = true;
                        for (int s = 0; s < count; ++s) {
                            rb::Sampler sampler(seed(), pixel, s);
                            const Vec2 u =
                                rb::stratifiedLensSample({seed(), pixel, s, count}, sampler);
                            const int cell =
                                static_cast<int>(u.y * rows) * cols + static_cast<int>(u.x * cols);
                            cells.insert(cell);
                            identity = identity && cell == s;
                        }
                        filled += static_cast<int>(cells.size()) == count;
                        shuffled += !identity;
                    }
                    // Every pixel's rays fill every cell once.
                    CHECK(filled == 20);
                    // The pairing of rays and cells differs from pixel to pixel.
                    if (count >= 16) CHECK(shuffled >= 18);
                }
            }
        }
    }
    GIVEN("the index permutation on its own") {
        THEN("it is a bijection of 0 … n − 1 for every n up to 300 and several keys") {
            int failures = 0;
            for (std::uint32_t n = 1; n <= 300; ++n)
                for (std::uint64_t key : {0ULL, 1ULL, 0x123456789abcdefULL, ~0ULL}) {
                    std::vector<int> hits(n, 0);
                    for (std::uint32_t i = 0; i < n; ++i) {
                        const std::uint32_t j = rb::permuteIndex(i, n, key);
                        if (j < n) ++hits[j];
                    }
                    for (int h : hits) failures += h != 1;
                }
            CHECK(failures == 0);
        }
    }
}
// [ch13-strata]

// [ch13-stratified-error]
SCENARIO("stratified lens samples blur an edge with less error than independent ones",
         "[ch13][ex13.2][ex13.3]") {
    GIVEN("an edge that covers the part x > 0.3 of the unit lens disk, seen from 2000 pixels") {
        // Source: the disk's area beyond x = a is acos(a) − a·√(1 − a²); over π it is the
        // exact fraction of the lens that sees the bright side.
        const double a = 0.3;
        const double exact = (std::acos(a) - a * std::sqrt(1.0 - a * a)) / glm::pi<double>();
        double squaredStratified = 0.0, squaredIndependent = 0.0;
        for (std::uint64_t pixel = 0; pixel < 2000; ++pixel) {
            double stratified = 0.0, independent = 0.0;
            for (int s = 0; s < 16; ++s) {
                rb::Sampler sampler(seed(), pixel, s);
                stratified +=
                    rb::concentricDisk(rb::stratifiedLensSample({seed(), pixel, s, 16}, sampler))
                        .x > a;
                rb::Sampler other(seed() + 1, pixel, s);
                independent += rb::concentricDisk(other.next2D()).x > a;
            }
            squaredStratified += std::pow(stratified / 16 - exact, 2);
            squaredIndependent += std::pow(independent / 16 - exact, 2);
        }
        THEN("16 stratified samples have under half the RMS error of 16 independent ones") {
            // Source: independent samples' RMS error is √(p(1−p)/16) ≈ 0.12 for p ≈ 0.31;
            // stratified, only the cells the edge crosses vary (about 4 of 16), so the
            // variance falls to about a quarter of it or less.
            const double rmsStratified = std::sqrt(squaredStratified / 2000);
            const double rmsIndependent = std::sqrt(squaredIndependent / 2000);
            INFO("stratified " << rmsStratified << ", independent " << rmsIndependent);
            CHECK(rmsIndependent == Approx(std::sqrt(exact * (1 - exact) / 16)).epsilon(0.1));
            CHECK(rmsStratified < 0.5 * rmsIndependent);
        }
    }
}
// [ch13-stratified-error]

// [ch13-rays-per-pixel]
SCENARIO("lens and pixel samples share rays: a pixel traces the larger count, not the product",
         "[ch13][ex13.1][ex13.2][ex13.3]") {
    const std::string lua = kBalls + kBallsRender + ")";
    const auto camerasPerPixel = [](const rb::World& w) {
        rb::RayCounters counters;
        rbtest::renderSmall(w, 20, 15, counters);
        return counters.count[static_cast<int>(rb::RayKind::Camera)] / (20.0 * 15.0);
    };
    GIVEN("the three-ball scene with a lens of 16 samples") {
        const std::string lens16 = "gr.lens{aperture = 0.3, samples = 16}\n" + lua;
        THEN("without antialiasing, 16 rays through each pixel centre") {
            CHECK(camerasPerPixel(*world(lens16)) == 16.0);
        }
        THEN("with jittered 4 × 4 antialiasing, still 16") {
            CHECK(camerasPerPixel(*world(lens16, {{"aa", "jittered"}, {"spp", "16"}})) == 16.0);
        }
        THEN("with a 2 × 2 uniform grid, the grid grows to 4 × 4: 16") {
            CHECK(camerasPerPixel(*world(lens16, {{"aa", "uniform"}, {"spp", "4"}})) == 16.0);
        }
        THEN("with 9 lens samples and 2 × 2 jittered, a 3 × 3 grid: 9") {
            CHECK(camerasPerPixel(*world(
                      lens16, {{"aa", "jittered"}, {"spp", "4"}, {"dof-samples", "9"}})) == 9.0);
        }
        THEN("with 64 random pixel samples, 64") {
            CHECK(camerasPerPixel(*world(lens16, {{"aa", "random"}, {"spp", "64"}})) == 64.0);
        }
    }
}
// [ch13-rays-per-pixel]

SCENARIO("depth-of-field images are the same for any thread count",
         "[ch13][ex13.1][ex13.2][ex13.3]") {
    GIVEN("the three-ball scene with a lens and jittered antialiasing") {
        const auto w = world(
            "gr.lens{aperture = 0.4, samples = 9}\n"
            "gr.antialias{sampler = 'jittered', samples = 4}\n" +
            kBalls + kBallsRender + ")");
        REQUIRE(installed(*w));
        THEN("1 and 2 threads give the same bits, and the image differs from the pinhole's") {
            rb::RayCounters c1, c2;
            const rb::Image one =
                rbtest::renderAt(*w, 40, 30, {.threads = 1, .samplesPerPixel = 1}, c1);
            const rb::Image two =
                rbtest::renderAt(*w, 40, 30, {.threads = 2, .samplesPerPixel = 1}, c2);
            CHECK(rbtest::bitIdentical(one, two));
            const auto pinhole = world("gr.antialias{sampler = 'jittered', samples = 4}\n" +
                                       kBalls + kBallsRender + ")");
            CHECK_FALSE(rbtest::bitIdentical(one, rbtest::renderSmall(*pinhole, 40, 30)));
        }
    }
}

// [ch13-settings]
SCENARIO("the lens is set by the command line, gr.lens, gr.option or seed 001's gr.render",
         "[ch13]") {
    const std::string lua = kBalls + kBallsRender + ")";
    GIVEN("a scene that asks for nothing") {
        THEN("no lens is installed: a pinhole") {
            CHECK(installed(*world(lua)) == nullptr);
        }
        THEN("--dof-aperture 0.2 installs a disk focused at |view| = 8 with 16 samples") {
            const auto w = world(lua, {{"dof-aperture", "0.2"}});
            REQUIRE(installed(*w));
            CHECK(installed(*w)->settings().aperture == 0.2);
            CHECK(installed(*w)->settings().focusDistance == 8.0);
            CHECK(installed(*w)->settings().samples == 16);
            CHECK(installed(*w)->settings().shape == rb::ApertureShape::Disk);
        }
        THEN("bad command-line values are refused") {
            CHECK_THROWS_WITH(world(lua, {{"dof-aperture", "-1"}}), Contains("0 (a pinhole)"));
            CHECK_THROWS_WITH(world(lua, {{"dof-aperture", "wide"}}),
                              Contains("expected a number"));
            CHECK_THROWS_WITH(world(lua, {{"dof-aperture", "1"}, {"dof-focus", "0"}}),
                              Contains("above 0"));
            CHECK_THROWS_WITH(world(lua, {{"dof-samples", "0"}}), Contains("lens samples"));
            CHECK_THROWS_WITH(world(lua, {{"dof-shape", "hexagon"}}), Contains("disk or square"));
        }
    }
    GIVEN("gr.lens{aperture = 0.3, focus = 5, samples = 25, shape = 'square'}") {
        const std::string lensLua =
            "gr.lens{aperture = 0.3, focus = 5, samples = 25, shape = 'square'}\n" + lua;
        THEN("it is read, and the command line wins over it") {
            const auto w = world(lensLua);
            REQUIRE(installed(*w));
            CHECK(installed(*w)->settings().aperture == 0.3);
            CHECK(installed(*w)->settings().focusDistance == 5.0);
            CHECK(installed(*w)->settings().samples == 25);
            CHECK(installed(*w)->settings().shape == rb::ApertureShape::Square);
            const auto cli = world(lensLua, {{"dof-focus", "9"}, {"dof-shape", "disk"}});
            CHECK(installed(*cli)->settings().focusDistance == 9.0);
            CHECK(installed(*cli)->settings().shape == rb::ApertureShape::Disk);
            CHECK(installed(*world(lensLua, {{"dof-aperture", "0"}})) == nullptr);
        }
        THEN("gr.option sets the same options one at a time") {
            const auto w = world(
                "gr.option('dof_aperture', 0.3)\ngr.option('dof_focus', 5)\n"
                "gr.option('dof_samples', 25)\ngr.option('dof_shape', 1)\n" +
                lua);
            REQUIRE(installed(*w));
            CHECK(installed(*w)->settings().focusDistance == 5.0);
            CHECK(installed(*w)->settings().shape == rb::ApertureShape::Square);
        }
        THEN("with chapter 13 switched off it loads, installs nothing, and says so") {
            const auto w = world(lensLua, {}, "all,-dof");
            CHECK(installed(*w) == nullptr);
            const rb::PinholeCamera camera(w->source.job.camera, 40, 30);
            const auto warnings = rb::renderWarnings(w->source.job, w->scene.instances, camera,
                                                     rbtest::chapters(13, "all,-dof"), "out.png");
            REQUIRE(warnings.size() == 1);
            CHECK_THAT(warnings[0], Contains("lens (gr.lens or dof_aperture) is ignored"));
        }
    }
    GIVEN("bad gr.lens calls") {
        const auto error = [&](const std::string& call) {
            return rbtest::loadError(call + "\n" + lua, rbtest::chapters(13));
        };
        THEN("each fails naming the field") {
            CHECK_THAT(error("gr.lens{aperture = -1}"), Contains("field 'aperture'"));
            CHECK_THAT(error("gr.lens{focus = 0}"), Contains("field 'focus'"));
            CHECK_THAT(error("gr.lens{samples = 2.5}"), Contains("field 'samples'"));
            CHECK_THAT(error("gr.lens{shape = 'hexagon'}"), Contains("'disk' or 'square'"));
            CHECK_THAT(error("gr.lens{apperture = 1}"), Contains("unknown field 'apperture'"));
            CHECK_THAT(error("gr.lens{aperture = 0/0}"), Contains("aperture"));
            CHECK_THAT(error("gr.lens(0.2)"), Contains("expects one table"));
        }
        THEN("without chapter 13, gr.lens names the chapter") {
            CHECK_THAT(rbtest::loadError("gr.lens{aperture = 1}\n" + lua, rbtest::chapters(8)),
                       Contains("chapter 13"));
        }
    }
    GIVEN("seed 001's gr.render(..., aa, ss, dist, {aperture, focalLength, dof})") {
        const std::string seed001 = kBalls + kBallsRender + ", 0, 0, 0, {0.4, 6, 3})";
        THEN("dof = 3 is a square aperture 0.4 wide, focused at 6, with 3² = 9 samples") {
            const auto w = world(seed001);
            REQUIRE(installed(*w));
            CHECK(installed(*w)->settings().aperture == 0.4);
            CHECK(installed(*w)->settings().focusDistance == 6.0);
            CHECK(installed(*w)->settings().samples == 9);
            CHECK(installed(*w)->settings().shape == rb::ApertureShape::Square);
        }
        THEN("dof = 0 is off whatever the aperture") {
            CHECK(installed(*world(kBalls + kBallsRender + ", 0, 0, 0, {0.4, 6, 0})")) == nullptr);
        }
        THEN("a fractional or negative dof is refused") {
            CHECK_THROWS_WITH(world(kBalls + kBallsRender + ", 0, 0, 0, {0.4, 6, 1.5})"),
                              Contains("whole number"));
        }
        THEN("chapter 13 reads it: no warning that the dof argument is ignored") {
            const auto w = world(seed001);
            const rb::PinholeCamera camera(w->source.job.camera, 40, 30);
            CHECK(rb::renderWarnings(w->source.job, w->scene.instances, camera,
                                     rbtest::chapters(13), "out.png")
                      .empty());
            const auto off = rb::renderWarnings(w->source.job, w->scene.instances, camera,
                                                rbtest::chapters(13, "all,-dof"), "out.png");
            REQUIRE(off.size() == 1);
            CHECK_THAT(off[0], Contains("dof argument (depth of field) is ignored"));
        }
    }
}
// [ch13-settings]

// [ch13-stability]
SCENARIO("extreme lenses give finite rays and images",
         "[ch13][stability][ex13.1][ex13.2][ex13.3]") {
    GIVEN(
        "lenses from a pinhole-thin aperture to one far wider than the scene, focused from "
        "1e-6 to 1e8 units") {
        const rb::PinholeCamera camera = tiltedCamera();
        int bad = 0;
        for (const double aperture : {1e-12, 1e-3, 1.0, 1e3, 1e6})
            for (const double focus : {1e-6, 1e-2, 1.0, 1e4, 1e8})
                for (const auto shape : {rb::ApertureShape::Disk, rb::ApertureShape::Square}) {
                    const rb::ThinLens thin = lens(aperture, focus, 4, shape);
                    // Image corners and lens samples at the square's edges and centre.
                    for (const Vec2 film : {Vec2(0, 0), Vec2(64, 48), Vec2(32, 24)})
                        for (const Vec2 u : {Vec2(0, 0), Vec2(0.5, 0.5), Vec2(1 - 1e-16, 0.5),
                                             Vec2(0.5, 1 - 1e-16), Vec2(0.25, 0.75)}) {
                            const rb::Ray r = thin.rayThrough(camera, film, u);
                            const bool finite = std::isfinite(r.o.x) && std::isfinite(r.o.y) &&
                                                std::isfinite(r.o.z) &&
                                                !rb::isDegenerateDirection(r.d) &&
                                                std::isfinite(glm::length(r.d));
                            bad += !finite || std::abs(glm::length(r.d) - 1.0) > 1e-12;
                        }
                }
        THEN("every ray has a finite origin and a unit direction") {
            CHECK(bad == 0);
        }
    }
    GIVEN("the concentric map at its centre, where the angle divides by zero") {
        THEN("the centre maps to the centre") {
            const Vec2 p = rb::concentricDisk(Vec2(0.5, 0.5));
            CHECK(p.x == 0.0);
            CHECK(p.y == 0.0);
        }
    }
    GIVEN("the three-ball scene through an aperture of 100 units focused 1e-4 ahead") {
        const auto w = world("gr.lens{aperture = 100, focus = 1e-4, samples = 4}\n" + kBalls +
                             kBallsRender + ")");
        THEN("the image is finite and non-negative") {
            CHECK(rbtest::allFiniteNonNegative(rbtest::renderSmall(*w, 20, 15)));
        }
    }
}
// [ch13-stability]
