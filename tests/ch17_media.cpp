/// \file
/// Chapter 17 tests: participating media.
///
/// Chapter 17 claims that tracking follows light through a medium without bias, whatever the
/// majorant, and that what the media scatter towards the eye is the radiative transfer
/// equation's answer. The tests check each estimator against a closed form: Beer–Lambert for
/// constant density and for a linear ramp (T = e^−(a d + b d²/2)), ray marching's exact error
/// on the ramp, z-tests of delta and ratio tracking at 1×, 2× and 10× the true majorant,
/// chi-square tests of free-flight distances and of the Henyey–Greenstein sampler, single
/// scattering in a slab lit from behind, L = π p(0) σs ℓ e^(−σt ℓ) I in A4's units, a
/// chi-square test of equiangular points, a lamp inside fog (with and without falloff) whose
/// single scattering free flights, light points and MIS all match (Simpson's rule of the
/// integral), a panel light whose lamp points take one of its strata each (its mean kept), a
/// surface behind homogeneous fog seen through exactly e^(−σt ℓ), and a furnace:
/// an albedo-1 medium under a uniform sky returns the sky. End to end: the image does
/// not depend on the majorant grid, the camera may sit inside a medium, concave, nested and
/// overlapping media hold the medium the scene graph says, interfaces cost no depth, a dense
/// medium (σ = 1000) renders without black or NaN pixels, a dense white medium lit by ambient
/// light alone returns no more than the ambient term (the term is counted once per path), and bad
/// media are refused.
/// Random streams use seed 1 (RB_CH17_SEED re-runs them on other streams).
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.h"
#include "lab/chi_square.h"
#include "media/equiangular.h"
#include "media/henyey_greenstein.h"
#include "media/media.h"
#include "media/medium.h"
#include "media/participating_media.h"
#include "media/tracking.h"
#include "soft_shadows/area_light.h"
#include "test_helpers.h"
#include "test_messages.h"

using Catch::Contains;
using rb::Colour;
using rb::Vec3;
using rbtest::meanAndError;
using rbtest::samples;
using rbtest::sidak;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The seed of every random stream in this file: 1, or RB_CH17_SEED.
std::uint64_t seed() {
    return rbtest::seedFromEnv("RB_CH17_SEED");
}

/// Density a + b·x inside the box [0, d]³ (zero outside), with its bound over a box scaled by
/// `slack` (1: the true maximum; 10: a majorant ten times too large).
class RampDensity final : public rb::DensityField {
  public:
    RampDensity(double a, double b, double d, double slack) : a_(a), b_(b), d_(d), slack_(slack) {}
    double at(const Vec3& p) const override {
        const bool inside = p.x >= 0 && p.x <= d_ && p.y >= 0 && p.y <= d_ && p.z >= 0 && p.z <= d_;
        return inside ? a_ + b_ * p.x : 0.0;
    }
    double maxIn(const Vec3&, const Vec3& hi) const override {
        return slack_ * (a_ + b_ * std::min(hi.x, d_));
    }
    rb::AABB bounds() const override { return rb::AABB{Vec3(0.0), Vec3(d_)}; }

  private:
    double a_, b_, d_, slack_;
};

/// Density 1 everywhere, but not flagged constant, so tracking (not the closed form) runs, with
/// a majorant `slack` times too large.
class TrackedConstant final : public rb::DensityField {
  public:
    explicit TrackedConstant(double slack) : slack_(slack) {}
    double at(const Vec3&) const override { return 1.0; }
    double maxIn(const Vec3&, const Vec3&) const override { return slack_; }
    rb::AABB bounds() const override {
        const double inf = std::numeric_limits<double>::infinity();
        return rb::AABB{Vec3(-inf), Vec3(inf)};
    }

  private:
    double slack_;
};

/// A grey medium of absorption sa and scattering ss with density field `density`.
rb::Medium medium(double sa, double ss, std::shared_ptr<const rb::DensityField> density,
                  double g = 0.0) {
    rb::Medium m;
    m.sigmaA = Colour(sa);
    m.sigmaS = Colour(ss);
    m.g = g;
    m.density = std::move(density);
    return m;
}

/// All space, as the shape box of a medium that is not inside a node.
rb::AABB everywhere() {
    const double inf = std::numeric_limits<double>::infinity();
    return rb::AABB{Vec3(-inf), Vec3(inf)};
}

/// The p-value of Pearson's chi-square test of observed counts against expected ones, with the
/// book's one implementation (src/lab/chi_square.h: bins expecting fewer than 5 pooled).
double chiSquarePValue(const std::vector<double>& observed, const std::vector<double>& expected) {
    return rb::chiSquareTest(observed, expected).pValue;
}

}  // namespace

SCENARIO("Light through a homogeneous medium falls off as Beer–Lambert says", "[ch17]") {
    GIVEN("a medium of σa = (0.1, 0.2, 0.3) and σs = (0.4, 0.3, 0.2) per unit length") {
        rb::Medium m;
        m.sigmaA = Colour(0.1, 0.2, 0.3);
        m.sigmaS = Colour(0.4, 0.3, 0.2);
        m.density = std::make_shared<rb::ConstantDensity>();
        const rb::TrackedMedium tracked(m, rb::Mat4(1.0), everywhere(), 16);
        rb::Sampler sampler(seed(), 0, 0);
        WHEN("a ray of direction length 2 crosses t = 0.5 to 2 (a distance of 3)") {
            const rb::Ray ray{Vec3(0.0), Vec3(0.0, 0.0, 2.0)};
            const Colour t = rb::estimateTransmittance(
                tracked, ray, 0.5, 2.0, rb::TransmittanceMethod::Ratio, 0.1, sampler);
            THEN("each channel is exactly e^(−σt·3)") {
                // Source: Beer–Lambert, T = exp(−σt d), σt = σa + σs = 0.5 in every channel.
                CHECK(t.r == Approx(std::exp(-1.5)).epsilon(1e-14));
                CHECK(t.g == Approx(std::exp(-1.5)).epsilon(1e-14));
                CHECK(t.b == Approx(std::exp(-1.5)).epsilon(1e-14));
            }
        }
    }
}

SCENARIO("Ray marching a linear ramp of density is off by exactly its jitter", "[ch17]") {
    GIVEN("density σ(x) = a + b·x with a = 0.5, b = 1 on x in [0, 1], and one majorant cell") {
        const double a = 0.5, b = 1.0, d = 1.0;
        const rb::Medium m = medium(0.0, 1.0, std::make_shared<RampDensity>(a, b, d, 1.0));
        const rb::TrackedMedium tracked(m, rb::Mat4(1.0), everywhere(), 1);
        const rb::Ray ray{Vec3(0.0, 0.5, 0.5), Vec3(1.0, 0.0, 0.0)};
        for (const int steps : {4, 16, 64}) {
            WHEN("it is marched in " + std::to_string(steps) + " steps of h = d/steps") {
                const double h = d / steps;
                rb::Sampler sampler(seed(), 7, 0), copy(seed(), 7, 0);
                const double u = copy.next1D();  // the jitter the march draws first
                const Colour t = rb::estimateTransmittance(
                    tracked, ray, 0.0, d, rb::TransmittanceMethod::March, h, sampler);
                THEN(
                    "its optical depth is a·d + b·d²/2 + b·d·h·(u − ½), the midpoint rule "
                    "shifted by the jitter") {
                    // Source: Σ_k (a + b (k + u) h) h over k < N = d/h is a d + b h² (N²/2 +
                    // N (u − ½)) = a d + b d²/2 + b d h (u − ½): exact for u = ½, first order in
                    // h otherwise, and exact on average over u.
                    const double tau = a * d + b * d * d / 2 + b * d * h * (u - 0.5);
                    CHECK(-std::log(t.r) == Approx(tau).epsilon(1e-12));
                }
            }
        }
    }
}

SCENARIO(
    "Delta and ratio tracking estimate a ramp's transmittance without bias, whatever the "
    "majorant",
    "[ch17][ex17.2][ex17.3]") {
    GIVEN("density σ(x) = 0.5 + 1·x on [0, 1], so T = e^−(0.5 + 0.5) = e^−1 across it") {
        // Source: T = exp(−∫σ) = exp(−(a d + b d²/2)).
        const double exact = std::exp(-1.0);
        const rb::Ray ray{Vec3(0.0, 0.5, 0.5), Vec3(1.0, 0.0, 0.0)};
        // Six z-tests together at family-wise level 0.001.
        const double z = rbtest::zCritical(sidak(0.001, 6));
        for (const double slack : {1.0, 2.0, 10.0})
            for (const auto method :
                 {rb::TransmittanceMethod::Ratio, rb::TransmittanceMethod::Delta}) {
                const char* name = method == rb::TransmittanceMethod::Ratio ? "ratio" : "delta";
                WHEN(std::string(name) + " tracking runs 10^6 times with the majorant at " +
                     std::to_string(static_cast<int>(slack)) + "× the true maximum") {
                    const rb::Medium m =
                        medium(0.2, 0.8, std::make_shared<RampDensity>(0.5, 1.0, 1.0, slack));
                    const rb::TrackedMedium tracked(m, rb::Mat4(1.0), everywhere(), 8);
                    const auto [mean, error] = meanAndError(1'000'000, [&](int i) {
                        rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 1);
                        return rb::estimateTransmittance(tracked, ray, 0.0, 1.0, method, 0.0,
                                                         sampler)
                            .r;
                    });
                    THEN("the mean lies within the z-test's bound of e^−1") {
                        INFO(rbtest::zReport(mean, exact, error) << " (e^−1)");
                        CHECK(std::abs(mean - exact) < z * error);
                    }
                }
            }
    }
}

SCENARIO("Spectral tracking through a coloured medium never gives a channel a negative weight",
         "[ch17][ex17.2]") {
    // Source: the soak's scene 1964 (tests/soak/README.md): its path-traced coloured fog left a
    // pixel's red at −2e−34. The null coefficient μ̄ − μa − μs of the largest channel is 0 in
    // exact arithmetic, and rounding can leave it a hair below; a majorant is a bound, so no
    // channel's null coefficient, and no weight, may be negative.
    GIVEN(
        "the soak scene's fog, σa = (1.80, 0.76, 0.46) and σs = (3.91, 1.68, 1.35) at density "
        "0.645, and rays of many lengths") {
        rb::Medium m;
        m.sigmaA = Colour(1.80, 0.76, 0.46) * 0.645;
        m.sigmaS = Colour(3.91, 1.68, 1.35) * 0.645;
        m.density = std::make_shared<rb::ConstantDensity>();
        const rb::TrackedMedium tracked(m, rb::Mat4(1.0), everywhere(), 16);
        WHEN("100,000 free flights are drawn, each along a ray of its own length") {
            int negative = 0;
            for (int i = 0; i < 100'000; ++i) {
                rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 3);
                const double length = 0.01 + 10.0 * sampler.next1D();
                const rb::Ray ray{Vec3(0.0), Vec3(length, 0.0, 0.0)};
                const rb::FreeFlight flight = rb::sampleFreeFlight(tracked, ray, 0.0, 1.0, sampler);
                const Colour w = flight.weight;
                if (w.r < 0.0 || w.g < 0.0 || w.b < 0.0) ++negative;
            }
            THEN("no flight's weight has a negative channel") {
                CHECK(negative == 0);
            }
        }
    }
}

SCENARIO("Free flights through a ramp are distributed as σ(t)·T(t)", "[ch17][ex17.2]") {
    GIVEN("a purely scattering ramp σ(x) = 0.5 + 2x on [0, 1], majorant 2× the maximum") {
        const rb::Medium m = medium(0.0, 1.0, std::make_shared<RampDensity>(0.5, 2.0, 1.0, 2.0));
        const rb::TrackedMedium tracked(m, rb::Mat4(1.0), everywhere(), 4);
        const rb::Ray ray{Vec3(0.0, 0.5, 0.5), Vec3(1.0, 0.0, 0.0)};
        WHEN("200000 flights are drawn from x = 0 to 1") {
            const int n = 200000, bins = 40;
            std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);
            for (int i = 0; i < n; ++i) {
                rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 2);
                const rb::FreeFlight f = rb::sampleFreeFlight(tracked, ray, 0.0, 1.0, sampler);
                REQUIRE(f.event != rb::FreeFlight::Event::Absorbed);
                if (f.event == rb::FreeFlight::Event::None)
                    observed[bins] += 1;
                else
                    observed[std::min(bins - 1, static_cast<int>(f.t * bins))] += 1;
            }
            // Source: P(collide before t) = 1 − T(t), T(t) = exp(−(0.5 t + t²)).
            const auto cdf = [](double t) { return 1.0 - std::exp(-(0.5 * t + t * t)); };
            for (int k = 0; k < bins; ++k)
                expected[k] = n * (cdf((k + 1.0) / bins) - cdf(double(k) / bins));
            expected[bins] = n * (1.0 - cdf(1.0));
            THEN("a chi-square test of the 40 distance bins and the escapes passes at 0.001") {
                const double p = chiSquarePValue(observed, expected);
                INFO("p = " << p);
                CHECK(p > 0.001);
            }
        }
    }
}

SCENARIO("The Henyey–Greenstein phase function is a pdf, and its sampler draws it",
         "[ch17][ex17.1]") {
    for (const double g : {-0.9, 0.0, 0.5, 0.9}) {
        GIVEN("g = " + std::to_string(g)) {
            THEN("2π ∫ p(μ) dμ over μ in [−1, 1] is 1") {
                // Simpson's rule on 20000 intervals; the peak at g = 0.9 is 1.9/(4π·0.001).
                const int n = 20000;
                double sum = 0.0;
                for (int i = 0; i <= n; ++i) {
                    const double mu = -1.0 + 2.0 * i / n;
                    const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
                    sum += w * rb::henyeyGreenstein(mu, g);
                }
                CHECK(2.0 * kPi * sum * (2.0 / n) / 3.0 == Approx(1.0).epsilon(1e-6));
            }
            WHEN("100000 directions are drawn around a forward axis") {
                const Vec3 forward = glm::normalize(Vec3(0.3, -0.5, 0.8));
                const int n = 100000, muBins = 20, phiBins = 8;
                std::vector<double> observed(muBins * phiBins, 0.0), expected(muBins * phiBins);
                // A frame to measure φ in.
                const Vec3 side = glm::normalize(glm::cross(forward, Vec3(0, 0, 1)));
                const Vec3 up = glm::cross(forward, side);
                for (int i = 0; i < n; ++i) {
                    rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 3);
                    const Vec3 w = rb::sampleHenyeyGreenstein(forward, g, sampler.next2D());
                    REQUIRE(glm::length(w) == Approx(1.0).epsilon(1e-12));
                    const double mu = glm::dot(w, forward);
                    const double phi = std::atan2(glm::dot(w, up), glm::dot(w, side)) + kPi;
                    const int a = std::min(muBins - 1, static_cast<int>((mu + 1.0) / 2.0 * muBins));
                    const int b =
                        std::min(phiBins - 1, static_cast<int>(phi / (2 * kPi) * phiBins));
                    observed[a * phiBins + b] += 1;
                }
                // Expected: 2π ∫ p dμ over each μ bin (Simpson, 200 intervals), split evenly
                // in φ, from the pdf itself rather than the sampler's inversion.
                for (int a = 0; a < muBins; ++a) {
                    const double lo = -1.0 + 2.0 * a / muBins, hi = lo + 2.0 / muBins;
                    double sum = 0.0;
                    for (int i = 0; i <= 200; ++i) {
                        const double w = (i == 0 || i == 200) ? 1 : (i % 2 ? 4 : 2);
                        sum += w * rb::henyeyGreenstein(lo + (hi - lo) * i / 200, g);
                    }
                    const double p = 2.0 * kPi * sum * ((hi - lo) / 200) / 3.0;
                    for (int b = 0; b < phiBins; ++b) expected[a * phiBins + b] = n * p / phiBins;
                }
                THEN("a chi-square test of 20 × 8 bins in (cos θ, φ) passes at 0.001 / 4") {
                    const double p = chiSquarePValue(observed, expected);
                    INFO("p = " << p << "; " << rbtest::warptestHint("hg-phase"));
                    CHECK(p > sidak(0.001, 4));
                }
            }
        }
    }
}

namespace {

/// A slab of medium m filling x in [0, ℓ] (a box node that only bounds it), lit by a light of
/// intensity 1 without falloff at `lamp` (x = 10 on the axis the camera ray looks along, unless
/// told otherwise).
struct Slab {
    Slab(const rb::Medium& m, double length, const std::map<std::string, std::string>& options,
         const Vec3& lamp = Vec3(10.0, 0.0, 0.0), const Vec3& falloff = Vec3(1.0, 0.0, 0.0),
         std::shared_ptr<const rb::LightShape> shape = nullptr) {
        world.add(box, rbtest::boxFromTo(Vec3(0.0, -5.0, -5.0), Vec3(length, 5.0, 5.0)), nullptr,
                  "slab");
        rb::Instance& slab = world.scene.instances.back();
        slab.medium = &m;
        slab.mediumBoundaryOnly = true;
        slab.mediumIndex = 0;
        rb::PointLight light;
        light.position = lamp;
        light.falloff = falloff;
        light.shape = std::move(shape);  // Before the build: chapter 6 samples it then.
        world.scene.lights.push_back(light);
        world.build(rbtest::chapters(17), -1, options);
    }
    rb::Box box;
    rbtest::TestWorld world;
};

/// The mean red radiance of `n` traces of `ray` through `slab` and its standard error, trace i
/// drawing from stream (seed(), i, `stream`).
std::pair<double, double> tracedMean(const Slab& slab, const rb::Ray& ray, int n,
                                     std::uint64_t stream) {
    return meanAndError(n, [&](int i) {
        rb::RayCounters counters;
        const rb::Integrator integrator(slab.world.scene, slab.world.pipeline);
        rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), stream);
        return integrator.trace(ray, sampler, counters, 0).r;
    });
}

/// Simpson's rule for the integral of f over [0, length] with `intervals` (even) intervals.
template <class F>
double simpson(const F& f, double length, int intervals) {
    double sum = f(0.0) + f(length);
    for (int k = 1; k < intervals; ++k) sum += (k % 2 ? 4.0 : 2.0) * f(k * length / intervals);
    return sum * length / intervals / 3.0;
}

}  // namespace

SCENARIO("A slab lit from behind shows single scattering's closed form",
         "[ch17][ex17.1][ex17.2][ex17.3][ex17.4]") {
    // Source: every point of the slab sees the light through e^(−σt (ℓ − s)) and the eye through
    // e^(−σt s), so L = ∫ σs p(cos 0) I e^(−σt ℓ) ds = σs p(1) ℓ e^(−σt ℓ) I, times π for A4's
    // lights (a white diffuse surface returns I cos θ / r², π times a physical light's).
    const double sa = 0.25, ss = 0.5, g = 0.5, length = 1.0;
    const double expected =
        kPi * rb::henyeyGreenstein(1.0, g) * ss * length * std::exp(-(sa + ss) * length);
    const std::map<std::string, std::string> single{{"media-bounces", "0"}};
    const rb::Ray ray{Vec3(-1.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)};
    const double z = rbtest::zCritical(sidak(0.001, 2));
    const int n = samples(200000);
    const std::string traced = "the ray along the axis is traced " + std::to_string(n) + " times";
    GIVEN("a homogeneous slab, σa = 0.25, σs = 0.5, g = 0.5, ℓ = 1, single scattering only") {
        const rb::Medium m = medium(sa, ss, std::make_shared<rb::ConstantDensity>(), g);
        const Slab slab(m, length, single);
        WHEN(traced) {
            const auto [mean, error] = tracedMean(slab, ray, n, 4);
            THEN("the radiance passes a z-test against π p(1) σs ℓ e^(−σt ℓ)") {
                INFO("mean " << mean << " ± " << error << " against " << expected);
                CHECK(std::abs(mean - expected) < z * error);
            }
        }
    }
    GIVEN("the same slab tracked as if heterogeneous, majorant 3× (delta and ratio tracking)") {
        const rb::Medium m = medium(sa, ss, std::make_shared<TrackedConstant>(3.0), g);
        const Slab slab(m, length, single);
        WHEN(traced) {
            const auto [mean, error] = tracedMean(slab, ray, n, 5);
            THEN("the radiance passes the same z-test") {
                INFO("mean " << mean << " ± " << error << " against " << expected);
                CHECK(std::abs(mean - expected) < z * error);
            }
        }
    }
    GIVEN(
        "a coloured slab: σa = (0.1, 0.3, 0.5), σs = (0.6, 0.4, 0.2), so each channel has "
        "its own σt") {
        // One path carries all three channels, drawn by the largest; spectral tracking's
        // weights keep each channel's mean at its own closed form.
        rb::Medium m = medium(0.0, 0.0, std::make_shared<TrackedConstant>(1.0), g);
        m.sigmaA = Colour(0.1, 0.3, 0.5);
        m.sigmaS = Colour(0.6, 0.4, 0.2);
        const Slab slab(m, length, single);
        WHEN(traced) {
            std::vector<Colour> traces(n);
            for (int i = 0; i < n; ++i) {
                rb::RayCounters counters;
                const rb::Integrator integrator(slab.world.scene, slab.world.pipeline);
                rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 7);
                traces[i] = integrator.trace(ray, sampler, counters, 0);
            }
            THEN(
                "each channel passes a z-test against π p(1) σs ℓ e^(−σt ℓ) with its own "
                "coefficients") {
                const double zc = rbtest::zCritical(sidak(0.001, 3));
                for (int c = 0; c < 3; ++c) {
                    const double want = kPi * rb::henyeyGreenstein(1.0, g) * m.sigmaS[c] * length *
                                        std::exp(-(m.sigmaA[c] + m.sigmaS[c]) * length);
                    const auto [mean, error] =
                        meanAndError(n, [&](int i) { return traces[i][c]; });
                    INFO("channel " << c << ": mean " << mean << " ± " << error << " against "
                                    << want);
                    CHECK(std::abs(mean - want) < zc * error);
                }
            }
        }
    }
}

SCENARIO("Equiangular points are spread as the angle under which the light sees them",
         "[ch17][ex17.4]") {
    // Source: Kulla and Fajardo 2012, eq. 6: θ(s) = atan((s − Δ) / h) is uniform between θ(a)
    // and θ(b), so P(s' < s) = (θ(s) − θ(a)) / (θ(b) − θ(a)).
    struct Case {
        const char* what;
        rb::EquiangularSegment seg;
    };
    for (const Case& c :
         {Case{"a light 0.25 off the middle of [0, 4]", {0.0, 4.0, 2.0, 0.25}},
          Case{"a light beyond the stretch's end", {0.0, 1.0, 3.0, 0.5}},
          Case{"a light almost on the ray's line, behind its start", {1.0, 2.0, -0.5, 1e-6}}})
        GIVEN(c.what) {
            const rb::EquiangularSegment seg = c.seg;
            const auto cdf = [&](double s) {
                const double at = std::atan((seg.a - seg.delta) / seg.h);
                return (std::atan((s - seg.delta) / seg.h) - at) /
                       (std::atan((seg.b - seg.delta) / seg.h) - at);
            };
            WHEN("100000 points are drawn") {
                const int n = 100000, bins = 40;
                std::vector<double> observed(bins, 0.0), expected(bins, 0.0);
                bool pdfAgrees = true;
                for (int i = 0; i < n; ++i) {
                    rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 8);
                    const rb::EquiangularSample e = rb::sampleEquiangular(seg, sampler.next1D());
                    const double x = (e.s - seg.a) / (seg.b - seg.a);
                    observed[std::clamp(static_cast<int>(x * bins), 0, bins - 1)] += 1;
                    pdfAgrees =
                        pdfAgrees && std::abs(e.pdf - rb::equiangularPdf(seg, e.s)) <= 1e-9 * e.pdf;
                }
                for (int k = 0; k < bins; ++k)
                    expected[k] = n * (cdf(seg.a + (k + 1.0) / bins * (seg.b - seg.a)) -
                                       cdf(seg.a + double(k) / bins * (seg.b - seg.a)));
                THEN("a chi-square test of 40 distance bins passes at 0.001") {
                    const double p = chiSquarePValue(observed, expected);
                    INFO("p = " << p << "; " << rbtest::warptestHint("equiangular"));
                    CHECK(p > sidak(0.001, 3));
                }
                THEN("each point's stated density is the pdf's") {
                    CHECK(pdfAgrees);
                }
            }
        }
}

SCENARIO("A walk's shadow rays played for by Russian roulette keep their light's mean",
         "[ch17][ex17.1]") {
    // Source: a particle at depth 0.6 of a slab ℓ = 1 (σs = 10, σa = 0.1, g = 0) sees the lamp
    // at x = 10 through the last 0.4 of the slab, T = e^(−10.1 · 0.4) = e^(−4.04), so it
    // scatters π p(1) T I = π (1 / 4π) e^(−4.04) = e^(−4.04) / 4 back along the axis (A4's
    // units, hence π). Russian roulette traces the shadow ray with a chance q and divides its
    // light by q: E = q · (L / q) = L, whatever q.
    const double sa = 0.1, ss = 10.0, length = 1.0;
    const double expected = 0.25 * std::exp(-(sa + ss) * 0.4);
    const rb::Medium m = medium(sa, ss, std::make_shared<rb::ConstantDensity>());
    const Slab slab(m, length, {});
    const auto* media =
        dynamic_cast<const rb::ParticipatingMedia*>(slab.world.pipeline.media.get());
    REQUIRE(media != nullptr);
    const rb::Integrator integrator(slab.world.scene, slab.world.pipeline);
    const Vec3 x(0.6, 0.0, 0.0), travel(-1.0, 0.0, 0.0);
    const double z = rbtest::zCritical(sidak(0.001, 2));
    // Both roulettes play here: T = 0.018 is below kShadowRouletteBelow, and the walk's guess
    // of 1e-4 sets the chance of tracing at all to kLeastShadowChance.
    REQUIRE(std::exp(-(sa + ss) * 0.4) < rb::kShadowRouletteBelow);
    REQUIRE(1e-4 / rb::kShadowRouletteBelow < rb::kLeastShadowChance);
    for (const double guess : {1.0, 1e-4})
        GIVEN("a particle at depth 0.6 of a slab σs = 10, σa = 0.1, ℓ = 1, the walk guessing " +
              std::to_string(guess) + " for its transmittance to the lamp") {
            WHEN("its light is estimated 400000 times") {
                double traced = 0.0;
                const auto [mean, error] = meanAndError(400000, [&](int i) {
                    rb::RayCounters counters;
                    rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 21);
                    const rb::ShadeContext ctx{slab.world.scene, integrator, sampler, counters, 0,
                                               rb::kNoMedia,     1.0,        false};
                    double g = guess;
                    const double light = media->walkLight(ctx, x, x, travel, m, g).r;
                    if (light > 0.0) traced += 1.0;
                    return light;
                });
                THEN("the mean passes a z-test against e^(−4.04) / 4, though few rays are traced") {
                    INFO("mean " << mean << " ± " << error << " against " << expected << ", "
                                 << traced / 4000.0 << "% of the shadow rays traced");
                    CHECK(std::abs(mean - expected) < z * error);
                    // The chance is T / kShadowRouletteBelow = 0.35, times 0.02 for the guess.
                    CHECK(traced < 0.5 * 400000);
                }
            }
        }
}

SCENARIO("A lamp inside fog: free flights, light points and both under MIS agree",
         "[ch17][ex17.1][ex17.2][ex17.4]") {
    // Source: single scattering along the ray p(x) = (x, 0, 0) through a slab x in [0, ℓ] with
    // a lamp of intensity 1 and falloff (c0, 0, c2) at q inside it is
    // L = ∫ σs π p(cos θ) e^(−σt r) / (c0 + c2 r²) e^(−σt x) dx, r = |q − p(x)| (A4's units,
    // hence π), integrated here by Simpson's rule: it has no simpler form.
    const double sa = 0.1, ss = 0.4, g = 0.5, length = 4.0;
    const Vec3 lamp(2.0, 0.5, 0.0);
    const rb::Medium m = medium(sa, ss, std::make_shared<rb::ConstantDensity>(), g);
    const rb::Ray ray{Vec3(-1.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)};
    const double z = rbtest::zCritical(sidak(0.001, 6));
    const int n = samples(100000);
    struct Lamp {
        const char* what;
        Vec3 falloff;
    };
    for (const Lamp& l :
         {Lamp{"A4's lamp without falloff (1, 0, 0): transmittance points", Vec3(1.0, 0.0, 0.0)},
          Lamp{"a physical lamp, falloff (0, 0, 1): equiangular points", Vec3(0.0, 0.0, 1.0)}})
        GIVEN(std::string(l.what) +
              ", 0.5 off the ray through a slab σa = 0.1, σs = 0.4, g = "
              "0.5, ℓ = 4") {
            const auto integrand = [&](double x) {
                const Vec3 toLamp = lamp - Vec3(x, 0.0, 0.0);
                const double r = glm::length(toLamp);
                return ss * kPi * rb::henyeyGreenstein(toLamp.x / r, g) * std::exp(-(sa + ss) * r) /
                       (l.falloff.x + l.falloff.z * r * r) * std::exp(-(sa + ss) * x);
            };
            double expected = simpson(integrand, length, 200000);
            WHEN("the ray along the axis is traced " + std::to_string(n) +
                 " times with each --media-direct") {
                std::map<std::string, std::pair<double, double>> estimates;
                for (const std::string direct : {"flight", "light", "mis"}) {
                    const Slab slab(m, length, {{"media-bounces", "0"}, {"media-direct", direct}},
                                    lamp, l.falloff);
                    estimates[direct] = tracedMean(slab, ray, n, 9);
                }
                THEN("each passes a z-test against the integral") {
                    for (const auto& [direct, estimate] : estimates) {
                        INFO(direct << ": mean " << estimate.first << " ± " << estimate.second
                                    << " against " << expected);
                        CHECK(std::abs(estimate.first - expected) < z * estimate.second);
                    }
                }
                THEN("MIS has a smaller standard error than free flights alone") {
                    INFO("MIS ± " << estimates["mis"].second << ", free flights ± "
                                  << estimates["flight"].second);
                    CHECK(estimates["mis"].second < estimates["flight"].second);
                }
            }
        }
}

SCENARIO("A panel light inside fog: lamp points that take one of its strata each keep its mean",
         "[ch17][ex17.1][ex17.4]") {
    // Source: the panel's light is the mean over its area A of a point light's, each point y
    // weighted by the panel's cosine towards the scattering point (chapter 6's samplePoint), so
    // along the ray p(x) = (x, 0, 0) single scattering is
    // L = ∫ σs e^(−σt x) (1/A) ∫_A π p(cos θ) e^(−σt r) max(0, n·(p − y)/r) dA dx, r = |y − p|
    // (A4's units, no falloff): Simpson's rule along the ray, the midpoint rule over the panel.
    const double sa = 0.1, ss = 0.4, g = 0.5, length = 4.0, side = 2.0;
    const Vec3 centre(2.0, 1.5, 0.0), normal(0.0, -1.0, 0.0), left(1.0, 0.0, 0.0);
    const Vec3 up = glm::cross(normal, left);
    const rb::Medium m = medium(sa, ss, std::make_shared<rb::ConstantDensity>(), g);
    const rb::Ray ray{Vec3(-1.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)};
    const double z = rbtest::zCritical(sidak(0.001, 2));
    const int n = samples(100000);
    GIVEN(
        "a 2 × 2 panel 1.5 above the ray, sampled at 3 × 3 points, in a slab σa = 0.1, "
        "σs = 0.4, g = 0.5, ℓ = 4, and 4 lamp points a ray (fewer than its 9 strata)") {
        const double st = sa + ss;
        const int cells = 40;
        const auto integrand = [&](double x) {
            const Vec3 at(x, 0.0, 0.0);
            double sum = 0.0;
            for (int i = 0; i < cells; ++i)
                for (int j = 0; j < cells; ++j) {
                    const Vec3 y = centre + ((i + 0.5) / cells - 0.5) * side * left +
                                   ((j + 0.5) / cells - 0.5) * side * up;
                    const Vec3 toLamp = y - at;
                    const double r = glm::length(toLamp);
                    const double cosLight = std::max(0.0, glm::dot(normal, -toLamp) / r);
                    sum +=
                        kPi * rb::henyeyGreenstein(toLamp.x / r, g) * std::exp(-st * r) * cosLight;
                }
            return ss * std::exp(-st * x) * sum / (cells * cells);
        };
        double expected = simpson(integrand, length, 400);
        WHEN("the ray is traced " + std::to_string(n) +
             " times by lamp points alone and by free flights alone") {
            std::map<std::string, std::pair<double, double>> estimates;
            for (const std::string direct : {"light", "flight"}) {
                const Slab slab(
                    m, length,
                    {{"media-bounces", "0"}, {"media-direct", direct}, {"media-points", "4"}},
                    centre, Vec3(1.0, 0.0, 0.0),
                    std::make_shared<rb::RectangleLight>(side, side, normal, left, 3));
                estimates[direct] = tracedMean(slab, ray, n, 12);
            }
            THEN("both pass a z-test against the integral") {
                for (const auto& [direct, estimate] : estimates) {
                    INFO(direct << ": mean " << estimate.first << " ± " << estimate.second
                                << " against " << expected);
                    CHECK(std::abs(estimate.first - expected) < z * estimate.second);
                }
            }
        }
    }
}

SCENARIO("A lamp inside a ramp of smoke: ratio-tracked lamp points and free flights agree",
         "[ch17][ex17.1][ex17.2][ex17.3]") {
    // Source: along the ray p(x) = (x, 1, 1) through a slab x in [0, ℓ] of density ρ(x) = a + bx,
    // with a lamp of intensity 1 without falloff at q, the ambient light A and a sky S behind,
    // L = ∫ σs ρ(x) π p(cos θ) e^(−σt τq(x)) e^(−σt τ(x)) dx + A σs/σt (1 − e^(−σt τ(ℓ)))
    //     + S e^(−σt τ(ℓ)),
    // τ(x) = a x + b x²/2 the optical depth from the slab's face and τq(x) = r (a + b (x + qx)/2)
    // the one to the lamp (a linear density's mean along a segment is its value at the middle);
    // the second term is ∫ σs ρ e^(−σt τ) dx in closed form. The first is integrated by
    // Simpson's rule.
    const double sa = 0.1, ss = 0.4, g = 0.5, length = 4.0, a = 0.5, b = 0.5;
    const double ambient = 0.1, sky = 0.25;
    const Vec3 lamp(2.0, 1.5, 1.0);
    // The density lives in the slab's unit cube (x/ℓ, (y + 5)/10, (z + 5)/10): a + bℓ·(x/ℓ).
    const rb::Medium m = medium(sa, ss, std::make_shared<RampDensity>(a, b * length, 1.0, 1.0), g);
    const rb::Ray ray{Vec3(-1.0, 1.0, 1.0), Vec3(1.0, 0.0, 0.0)};
    const double z = rbtest::zCritical(sidak(0.001, 3));
    const int n = samples(100000);
    GIVEN(
        "density 0.5 + 0.5x, σa = 0.1, σs = 0.4, g = 0.5, ℓ = 4, a lamp 0.5 off the ray, "
        "ambient light 0.1 and a sky of 0.25") {
        const double st = sa + ss;
        const auto depth = [&](double x) { return a * x + b * x * x / 2.0; };
        const auto integrand = [&](double x) {
            const Vec3 toLamp = lamp - Vec3(x, 1.0, 1.0);
            const double r = glm::length(toLamp);
            const double toLampDepth = r * (a + b * (x + lamp.x) / 2.0);
            return ss * (a + b * x) * kPi * rb::henyeyGreenstein(toLamp.x / r, g) *
                   std::exp(-st * toLampDepth) * std::exp(-st * depth(x));
        };
        double expected = simpson(integrand, length, 200000);
        const double through = std::exp(-st * depth(length));
        expected += ambient * ss / st * (1.0 - through) + sky * through;
        WHEN("the ray is traced " + std::to_string(n) + " times with each --media-direct") {
            std::map<std::string, std::pair<double, double>> estimates;
            for (const std::string direct : {"flight", "light", "mis"}) {
                Slab slab(m, length, {{"media-bounces", "0"}, {"media-direct", direct}}, lamp);
                slab.world.scene.ambient = Colour(ambient);
                slab.world.scene.background = Colour(sky);
                estimates[direct] = tracedMean(slab, ray, n, 11);
            }
            THEN("each passes a z-test against the integral") {
                for (const auto& [direct, estimate] : estimates) {
                    INFO(direct << ": mean " << estimate.first << " ± " << estimate.second
                                << " against " << expected);
                    CHECK(std::abs(estimate.first - expected) < z * estimate.second);
                }
            }
            THEN("the ratio-tracked points have a smaller standard error than free flights") {
                INFO("points ± " << estimates["mis"].second << ", free flights ± "
                                 << estimates["flight"].second);
                CHECK(estimates["mis"].second < estimates["flight"].second);
            }
        }
    }
}

SCENARIO(
    "A surface behind homogeneous fog is seen through Beer–Lambert's transmittance, with no "
    "noise",
    "[ch17]") {
    // Source: the first ray's surface is weighted by the closed form e^(−σt ℓ), apart from the
    // light the fog scatters (none here: no lights, no ambient light).
    GIVEN("a slab σa = 0.25, σs = 0.5, ℓ = 1 before a sky of radiance 1, with no lights") {
        const rb::Medium m = medium(0.25, 0.5, std::make_shared<rb::ConstantDensity>(), 0.0);
        Slab slab(m, 1.0, {{"media-bounces", "0"}});
        slab.world.scene.lights.clear();
        slab.world.scene.background = Colour(1.0);
        slab.world.scene.ambient = Colour(0.0);
        WHEN("the ray along the axis is traced 1000 times") {
            double lowest = 2.0, highest = -1.0;
            for (int i = 0; i < 1000; ++i) {
                rb::RayCounters counters;
                const rb::Integrator integrator(slab.world.scene, slab.world.pipeline);
                rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 10);
                const double l = integrator
                                     .trace(rb::Ray{Vec3(-1.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)},
                                            sampler, counters, 0)
                                     .g;
                lowest = std::min(lowest, l);
                highest = std::max(highest, l);
            }
            THEN("every trace returns e^(−0.75), not 0 or 1") {
                CHECK(lowest == Approx(std::exp(-0.75)).epsilon(1e-12));
                CHECK(highest == Approx(std::exp(-0.75)).epsilon(1e-12));
            }
        }
    }
}

SCENARIO("A media furnace: an albedo-1 medium under a uniform sky gives back the sky",
         "[ch17][ex17.2]") {
    // Source: with no absorption and a sky of radiance 1 on every side, radiance is 1 everywhere
    // inside and in every direction, whatever the density and the phase function.
    for (const double tau : {0.1, 1.0, 10.0, 100.0})
        for (const double g : {-0.9, 0.0, 0.9}) {
            GIVEN("a unit ball of σs = " + std::to_string(tau) +
                  " (σt R = σs), g = " + std::to_string(g) + ", seen from its centre") {
                const rb::Medium m = medium(0.0, tau, std::make_shared<rb::ConstantDensity>(), g);
                rbtest::TestWorld world;
                world.addSphere(rb::Mat4(1.0), nullptr, "ball");
                rb::Instance& ball = world.scene.instances.back();
                ball.medium = &m;
                ball.mediumBoundaryOnly = true;
                ball.mediumIndex = 0;
                world.scene.background = Colour(1.0);
                world.scene.minWeight = 0.0;
                // The default settings: no cap on the walk (a cap of 256 scatterings returned 0
                // for the paths it cut, about ten thousand scatterings short at σs = 100).
                world.build(rbtest::chapters(17), -1);
                WHEN("paths start in random directions, under the default settings") {
                    const int n = tau >= 100.0 ? 40 : 400;
                    rbtest::Rng rng(seed());
                    double lowest = 2.0, highest = 0.0;
                    for (int i = 0; i < n; ++i) {
                        rb::RayCounters counters;
                        const rb::Integrator integrator(world.scene, world.pipeline);
                        rb::Sampler sampler(seed(), static_cast<std::uint64_t>(i), 6);
                        const double l =
                            integrator
                                .trace(rb::Ray{Vec3(0.0), rng.unitVector()}, sampler, counters, 0)
                                .g;
                        lowest = std::min(lowest, l);
                        highest = std::max(highest, l);
                    }
                    THEN("every path returns the sky's radiance, 1") {
                        CHECK(lowest == Approx(1.0).epsilon(1e-9));
                        CHECK(highest == Approx(1.0).epsilon(1e-9));
                    }
                }
            }
        }
}

namespace {

/// A scene with a medium box (a node without a material, so only a boundary) in front of a
/// white wall lit by one light; `extra` adds to it, `medium` is the gr.medium table.
std::string mediumScene(const std::string& medium, const std::string& extra = "") {
    return R"(
local root = gr.node('root')
local wall = gr.cube('wall')
wall:scale(4, 4, 0.2)
wall:translate(-2, -2, -2)
wall:set_material(gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1))
root:add_child(wall)
local box = gr.cube('smoke')
box:scale(2, 2, 2)
box:translate(-1, -1, -1.5)
box:set_medium(gr.medium)" +
           medium + R"()
root:add_child(box)
)" + extra +
           R"(
gr.render(root, 'x.png', 32, 32, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 40, {0.1, 0.1, 0.1},
          {gr.light({1, 2, 3}, {1, 1, 1}, {1, 0, 0})})
)";
}

/// Render `lua` on `threads` threads at 32 × 32 with `spp` samples and these options.
rb::Image renderMedia(const std::string& lua, int spp,
                      const std::map<std::string, std::string>& options = {}, int threads = 1) {
    const auto world = rbtest::worldFromLua(lua, rbtest::chapters(17), options);
    rb::RenderSettings settings;
    settings.threads = threads;
    settings.samplesPerPixel = spp;
    settings.seed = seed();
    rb::RayCounters counters;
    return rbtest::renderAt(*world, 32, 32, settings, counters);
}

}  // namespace

SCENARIO("The image does not depend on the majorant", "[ch17][ex17.2][ex17.3]") {
    GIVEN("a lit wall behind a box of ramp smoke, σ(x) = 0.2 + 3x in the box's own space") {
        // 32 × 32 pixels looking at the box, 64 paths each (6 in the sanitizer tree), for one
        // majorant set-up.
        const int paths = samples(64);
        const auto render = [paths](double slack, int cells) {
            const rb::Medium m =
                medium(0.5, 2.0, std::make_shared<RampDensity>(0.2, 3.0, 1.0, slack), 0.3);
            rb::Box box;
            rbtest::TestWorld world;
            const rb::Material* white =
                world.material(rb::Material{Colour(0.8), Colour(0.0), 1.0, {}, {}});
            world.addBox(rbtest::boxFromTo(Vec3(-2, -2, -2.2), Vec3(2, 2, -2)), white, "wall");
            world.add(box, rbtest::boxFromTo(Vec3(-1, -1, -1.5), Vec3(1, 1, 0.5)), nullptr,
                      "smoke");
            rb::Instance& smoke = world.scene.instances.back();
            smoke.medium = &m;
            smoke.mediumBoundaryOnly = true;
            smoke.mediumIndex = 0;
            rb::PointLight light;
            light.position = Vec3(1, 2, 3);
            world.scene.lights.push_back(light);
            world.build(rbtest::chapters(17), -1, {{"media-majorant", std::to_string(cells)}});
            const rb::Integrator integrator(world.scene, world.pipeline);
            std::vector<double> image(32 * 32, 0.0);
            for (int p = 0; p < 32 * 32; ++p) {
                const Vec3 target(-1.2 + 2.4 * (p % 32 + 0.5) / 32,
                                  -1.2 + 2.4 * (p / 32 + 0.5) / 32, 0.5);
                for (int k = 0; k < paths; ++k) {
                    rb::Sampler sampler(seed(), static_cast<std::uint64_t>(p), k + 64 * cells);
                    rb::RayCounters counters;
                    image[p] += integrator
                                    .trace(rb::Ray{Vec3(0, 0, 4), target - Vec3(0, 0, 4)}, sampler,
                                           counters, 0)
                                    .g /
                                paths;
                }
            }
            return image;
        };
        WHEN(
            "it is rendered with the true maximum in one cell, and with 10× majorants in 16³ "
            "cells") {
            const std::vector<double> tight = render(1.0, 1), loose = render(10.0, 16);
            THEN("the pixel differences have mean zero (a t-test over the 1024 pixels)") {
                // The two renders draw different numbers, so each pixel's difference is noise
                // with mean zero when both are unbiased.
                const auto [mean, error] =
                    meanAndError(32 * 32, [&](int i) { return tight[i] - loose[i]; });
                INFO("mean difference " << mean << " ± " << error);
                CHECK(error > 0.0);
                CHECK(std::abs(mean) < rbtest::zCritical(0.001) * error);
            }
        }
    }
}

SCENARIO("Media renders are the same bits on one thread and two",
         "[ch17][ex17.1][ex17.2][ex17.3]") {
    GIVEN("a box of noise smoke in front of a lit wall") {
        const std::string lua = mediumScene("{sigma_s = 2, density = {noise = 1.5, bias = 0.3}}");
        THEN("one thread and two give identical images") {
            CHECK(rbtest::bitIdentical(renderMedia(lua, 4, {}, 1), renderMedia(lua, 4, {}, 2)));
        }
    }
}

SCENARIO("Media sit where the scene graph puts them", "[ch17]") {
    const auto transmittanceThrough = [](const std::string& lua, const Vec3& a, const Vec3& b) {
        const auto world = rbtest::worldFromLua(lua, rbtest::chapters(17));
        REQUIRE(world->pipeline.media != nullptr);
        rb::Sampler sampler(seed(), 0, 0);
        rb::RayCounters counters;
        return world->pipeline.media->transmittance(a, b, sampler, counters).r;
    };
    // Each crossing restarts the ray just beyond the surface (the ray offset, ~1e-9 of the
    // coordinates), so lengths inside agree to about 1e-9 per crossing: 1e-8 below.
    const std::string light =
        "gr.render(root, 'x.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, "
        "40, {0, 0, 0}, {gr.light({0, 9, 0}, {1, 1, 1}, {1, 0, 0})})\n";
    GIVEN("a ball of radius 1 with σt = 1 at the origin") {
        const std::string lua =
            "local root = gr.node('root')\n"
            "local s = gr.sphere('s')\n"
            "s:set_medium(gr.medium{sigma_s = 1})\n"
            "root:add_child(s)\n" +
            light;
        THEN(
            "a segment that starts inside it (a camera in the fog) is dimmed by its length "
            "inside, e^−1 from the centre out") {
            CHECK(transmittanceThrough(lua, Vec3(0.0), Vec3(0, 0, 5)) ==
                  Approx(std::exp(-1.0)).epsilon(1e-8));
            CHECK(transmittanceThrough(lua, Vec3(0, 0, -0.5), Vec3(0, 0, 0.5)) ==
                  Approx(std::exp(-1.0)).epsilon(1e-8));
        }
    }
    GIVEN("a concave medium: a 2 × 2 × 2 box with a ball of radius 0.8 cut out of it (CSG)") {
        const std::string lua =
            "local root = gr.node('root')\n"
            "local b = gr.cube('b') b:scale(2, 2, 2) b:translate(-1, -1, -1)\n"
            "local s = gr.sphere('s') s:scale(0.8, 0.8, 0.8)\n"
            "local c = gr.difference(b, s, 'c')\n"
            "c:set_medium(gr.medium{sigma_s = 1})\n"
            "root:add_child(c)\n" +
            light;
        THEN("a ray through the middle is dimmed only by the two walls of 0.2: e^−0.4") {
            CHECK(transmittanceThrough(lua, Vec3(0, 0, -3), Vec3(0, 0, 3)) ==
                  Approx(std::exp(-0.4)).epsilon(1e-8));
        }
    }
    GIVEN("a ball of σt = 3 and radius 0.5 nested (as a child) in a ball of σt = 1, radius 1") {
        const std::string lua =
            "local root = gr.node('root')\n"
            "local outer = gr.sphere('outer')\n"
            "outer:set_medium(gr.medium{sigma_s = 1})\n"
            "local inner = gr.sphere('inner') inner:scale(0.5, 0.5, 0.5)\n"
            "inner:set_medium(gr.medium{sigma_s = 3})\n"
            "outer:add_child(inner)\n"
            "root:add_child(outer)\n" +
            light;
        THEN("the inner medium replaces the outer inside it: e^−(1·1 + 3·1)") {
            CHECK(transmittanceThrough(lua, Vec3(0, 0, -3), Vec3(0, 0, 3)) ==
                  Approx(std::exp(-4.0)).epsilon(1e-8));
        }
    }
    GIVEN("two overlapping sibling balls, σt = 1 then σt = 2, centres 1 apart on z") {
        const std::string lua =
            "local root = gr.node('root')\n"
            "local a = gr.sphere('a')\n"
            "a:set_medium(gr.medium{sigma_s = 1})\n"
            "local b = gr.sphere('b') b:translate(0, 0, 1)\n"
            "b:set_medium(gr.medium{sigma_s = 2})\n"
            "root:add_child(a) root:add_child(b)\n" +
            light;
        THEN("the later node fills the overlap: e^−(1·1 + 2·2) along the z axis") {
            // a covers z in [−1, 1], b covers [0, 2]: a alone on [−1, 0], b on [0, 2].
            CHECK(transmittanceThrough(lua, Vec3(0, 0, -3), Vec3(0, 0, 3)) ==
                  Approx(std::exp(-5.0)).epsilon(1e-8));
        }
    }
    GIVEN("a lit wall behind twenty nested medium shells that scatter nothing") {
        std::string lua = mediumScene("{sigma_s = 0, sigma_a = 0}");
        std::string shells = "local parent = box\n";
        for (int k = 1; k <= 20; ++k)
            shells += "local s" + std::to_string(k) + " = gr.sphere('s" + std::to_string(k) +
                      "') s" + std::to_string(k) + ":scale(0.95, 0.95, 0.95)\n" + "s" +
                      std::to_string(k) + ":set_medium(gr.medium{sigma_s = 0})\n" +
                      "parent:add_child(s" + std::to_string(k) + ") parent = s" +
                      std::to_string(k) + "\n";
        lua = mediumScene("{sigma_s = 0, sigma_a = 0}", shells);
        THEN(
            "with --max-depth 1 the wall still shades as without them: interfaces cost no "
            "depth") {
            const auto with = rbtest::worldFromLua(lua, rbtest::chapters(17));
            with->scene.maxDepth = 1;
            const Colour c = rbtest::traceOne(*with, rb::Ray{Vec3(0, 0, 4), Vec3(0, 0, -1)});
            CHECK(c.r > 0.5);
        }
    }
}

SCENARIO("A dense medium renders without black or NaN pixels", "[ch17][ex17.1][ex17.2]") {
    GIVEN("a white box of smoke with σs = 1000, no absorption, lit from the front-right") {
        const std::string lua = mediumScene("{sigma_s = 1000}");
        WHEN("it is rendered") {
            const rb::Image image = renderMedia(lua, 4);
            THEN("every pixel is finite, and every pixel of the box's face is lit") {
                CHECK(rbtest::allFiniteNonNegative(image));
                // The box covers the middle of the view; its face scatters the light back. A4's
                // ambient (0.1, counted once per path) alone would give 0.1, and single
                // scattering adds about an eighth of a white wall's light (the first particle
                // sees the light through the cloud only at grazing depth), together about 0.14;
                // multiple scattering brings the face near a white wall's 0.5 to 0.9 (mean 0.76
                // at 16 paths; at these 4 paths the darkest pixel is 0.31). So a face darker
                // than 0.25 means the light got lost in the cloud.
                float darkest = 1e9f;
                for (int y = 12; y < 20; ++y)
                    for (int x = 12; x < 20; ++x)
                        darkest = std::min(darkest, image.data()[3 * (y * 32 + x)]);
                INFO("darkest pixel of the face " << darkest);
                CHECK(darkest > 0.25f);
            }
        }
    }
}

SCENARIO("A walk's near flights deep inside a lone medium change no bit",
         "[ch17][ex17.1][ex17.2]") {
    // Source: nearFlight draws the numbers the full flight would draw (a copy of the sampler,
    // kept only when the flight ends nearer than the boundary can be), so the same path
    // results. A depth that overstated the boundary's distance would let flights leave the
    // medium unseen: those paths, and so the pixels, would differ.
    const auto same = [](const std::string& lua) {
        const rb::Image on = renderMedia(lua, 4);
        const rb::Image off = renderMedia(lua, 4, {{"media-near-flights", "off"}});
        return rbtest::bitIdentical(on, off);
    };
    GIVEN("a dense box of smoke (σs = 200) that no other shape's bounds meet") {
        THEN("the image is the same bits with near flights on and off") {
            CHECK(same(mediumScene("{sigma_s = 200, sigma_a = 0.05}")));
        }
    }
    GIVEN("a dense ellipsoid, turned 30° about x and y, then scaled (0.6, 1.2, 0.9)") {
        // Not a rotation times one scale: the bound on how far it stretches (worldPerObject)
        // is then below the true one, never above.
        const std::string lua = R"(
local root = gr.node('root')
local egg = gr.sphere('egg')
egg:rotate('x', 30)
egg:rotate('y', 30)
egg:scale(0.6, 1.2, 0.9)
egg:set_medium(gr.medium{sigma_s = 80, sigma_a = 0.1})
root:add_child(egg)
gr.render(root, 'x.png', 32, 32, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 40, {0.1, 0.1, 0.1},
          {gr.light({1, 2, 3}, {1, 1, 1}, {1, 0, 0})})
)";
        THEN("the image is the same bits with near flights on and off") {
            CHECK(same(lua));
        }
    }
    GIVEN("the dense box with a white ball inside it (the box is not lone: no near flights)") {
        const std::string lua = mediumScene("{sigma_s = 200}", R"(
local ball = gr.sphere('ball')
ball:scale(0.3, 0.3, 0.3)
ball:translate(0, 0, -0.5)
ball:set_material(gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1))
root:add_child(ball)
)");
        THEN("the image is the same bits with near flights on and off") {
            CHECK(same(lua));
        }
    }
}

SCENARIO("A shape says how deep a point lies inside it", "[ch17]") {
    // Source: the unit sphere's surface is 1 − |p| from an inner point p; the unit cube's is
    // the nearest of the six faces, min(p, 1 − p) over the axes.
    GIVEN("the unit sphere") {
        const rb::Sphere sphere;
        THEN("(0.3, 0.4, 0) lies 0.5 deep, its centre 1, and a point outside 0") {
            CHECK(sphere.depthInside(Vec3(0.3, 0.4, 0.0)) == Approx(0.5));
            CHECK(sphere.depthInside(Vec3(0.0)) == Approx(1.0));
            CHECK(sphere.depthInside(Vec3(1.5, 0.0, 0.0)) == 0.0);
        }
    }
    GIVEN("the unit cube") {
        const rb::Box box;
        THEN("(0.2, 0.5, 0.9) lies 0.1 deep, its centre 0.5, and a point outside 0") {
            CHECK(box.depthInside(Vec3(0.2, 0.5, 0.9)) == Approx(0.1));
            CHECK(box.depthInside(Vec3(0.5)) == Approx(0.5));
            CHECK(box.depthInside(Vec3(-0.1, 0.5, 0.5)) == 0.0);
        }
    }
}

SCENARIO(
    "An ambient furnace: a dense white medium lit by ambient light alone returns no more "
    "than the ambient term",
    "[ch17][ex17.1][ex17.2]") {
    // Source: A4's ambient term stands for all the indirect light, so a path counts it once, at
    // its first scattering, as a diffuse surface does (DESIGN §6: the ambient term is counted once
    // per camera path). With no lights and a black sky, every path that scatters returns exactly
    // the ambient A, and one that does not returns 0: a pixel is A times the fraction of its
    // paths that scatter, never more. A path that counted A at each of its hundreds of
    // scatterings in a cloud of albedo 1 returned up to 1/(1 − albedo) times A.
    GIVEN("a ball of a milk-like medium (σs = 45, σa = 0, no surface), ambient 0.1, a dark light") {
        const std::string lua = R"(
local root = gr.node('root')
local milk = gr.sphere('milk')
milk:set_medium(gr.medium{sigma_s = 45, sigma_a = 0})
root:add_child(milk)
gr.render(root, 'x.png', 32, 32, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 40, {0.1, 0.1, 0.1},
          {gr.light({1, 2, 3}, {0, 0, 0}, {1, 0, 0})})
)";
        WHEN("it is rendered with 4 paths a pixel") {
            const rb::Image image = renderMedia(lua, 4);
            THEN("no pixel reads more than the ambient term, and the ball's middle reads it") {
                float brightest = 0.0f, middle = 1e9f;
                for (int y = 0; y < 32; ++y)
                    for (int x = 0; x < 32; ++x) {
                        const float v = image.data()[3 * (y * 32 + x)];
                        brightest = std::max(brightest, v);
                        if (x >= 14 && x < 18 && y >= 14 && y < 18) middle = std::min(middle, v);
                    }
                INFO("brightest pixel " << brightest << ", darkest of the middle " << middle);
                // The float film rounds 0.1 to within 1e-7.
                CHECK(brightest <= 0.1f + 1e-6f);
                // Through the middle the ball is 2 units of σt = 45: e^−90 of the paths cross
                // it without scattering.
                CHECK(middle >= 0.1f - 1e-6f);
            }
        }
    }
}

SCENARIO("A scene without media pays nothing for chapter 17", "[ch17]") {
    GIVEN("chapter 16's scene, which calls no media") {
        std::ifstream in(rbtest::sourceDir() + "/scenes/chapter16-photon-mapping.lua");
        const std::string lua{std::istreambuf_iterator<char>(in), {}};
        const auto world = rbtest::worldFromLua(lua, rbtest::chapters(17));
        THEN("no media term is installed") {
            CHECK(world->pipeline.media == nullptr);
        }
    }
}

SCENARIO("Bad media are refused with the call and what was expected", "[ch17]") {
    const auto error = [](const std::string& medium) {
        return rbtest::loadError(mediumScene(medium), rbtest::chapters(17));
    };
    THEN("negative coefficients, |g| ≥ 1, unknown fields and bad densities are refused") {
        CHECK_THAT(error("{sigma_a = -1}"),
                   Contains("scene.lua:") && Contains("sigma_a") && Contains("≥ 0"));
        CHECK_THAT(error("{sigma_s = {1, -2, 1}}"), Contains("sigma_s") && Contains("≥ 0"));
        CHECK_THAT(error("{g = 1}"), Contains("'g'") && Contains("between −1 and 1"));
        CHECK_THAT(error("{g = -1.5}"), Contains("'g'"));
        CHECK_THAT(error("{sigma = 1}"), Contains("unknown field 'sigma'"));
        CHECK_THAT(error("{density = -2}"), Contains("density") && Contains("≥ 0"));
        CHECK_THAT(error("{density = 'thick'}"), Contains("density"));
        CHECK_THAT(error("{density = {noise = 0}}"), Contains("frequency"));
        CHECK_THAT(error("{sigma_s = 0/0}"), Contains("sigma_s"));
    }
    THEN("a medium on a node without a shape, and a fog that is not a medium, are refused") {
        CHECK_THAT(rbtest::loadError("local n = gr.node('n')\nn:set_medium(gr.medium{})\n",
                                     rbtest::chapters(17)),
                   Contains("scene.lua:2") && Contains("has no shape"));
        CHECK_THAT(rbtest::loadError("gr.fog(3)\n", rbtest::chapters(17)),
                   Contains("scene.lua:1") && Contains("must be a medium"));
    }
    THEN("bad options are refused, naming the option") {
        const std::string lua = mediumScene("{}");
        CHECK_THROWS_WITH(rbtest::worldFromLua(lua, rbtest::chapters(17), {{"media", "fast"}}),
                          Contains("--media"));
        CHECK_THROWS_WITH(
            rbtest::worldFromLua(lua, rbtest::chapters(17), {{"media-majorant", "1000"}}),
            Contains("--media-majorant"));
        CHECK_THROWS_WITH(rbtest::worldFromLua(lua, rbtest::chapters(17), {{"media-step", "0"}}),
                          Contains("--media-step"));
    }
}
