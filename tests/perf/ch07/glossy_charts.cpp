// Chapter 7's chart data (make charts): the fuzz sphere against the Phong lobe.
//
//   ch07_glossy_charts SCENE OUT_DIR
//
// writes into OUT_DIR:
//   equal-time.dat   sampler, directions N, render CPU seconds, RMSE against that sampler's
//                    own converged reference (2 × 1024 directions), for N = 1 … 128
//   finding.txt      one sentence with the numbers, for the chapter page
//   grazing.dat      the fraction of lobe samples lost below the surface against the mirror
//                    direction's elevation, for both samplers at glossiness 0.1 and 0.3
//   lobe-shapes.dat  p(α)/p(0) for both lobes at glossiness 0.05, 0.15 and 0.4
//   lobes.png        the chapter scene as it is, fuzz | lobe, 192×144, 8 samples per pixel
//
// The scene is the chapter scene at 128×96, as it is (max_depth 4). traceSpecular spreads a
// lobe into N rays only where the camera sees a glossy surface and takes one sample at deeper
// glossy bounces, so the cost is linear in N and a converged reference is affordable. Time is
// the process's CPU time (both threads), which a busy shared machine disturbs less than
// wall-clock time; each point is the fastest of 3 runs.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "chart_helpers.h"
#include "scene/chapter_features.h"
#include "phong/phong.h"
#include "bvh/bvh_aggregate.h"
#include "core/image.h"
#include "glossy/glossy.h"
#include "glossy/lobe_samplers.h"
#include "reflection/reflection.h"
#include "refraction/refraction.h"
#include "soft_shadows/soft_shadows.h"

namespace {

constexpr int kWidth = 128, kHeight = 96;
constexpr double kPi = 3.14159265358979323846;

/// The chapter scene built as `rt` builds it, with the given glossy options.
std::unique_ptr<rb::World> buildWorld(const std::string& path, const std::string& sampler,
                                      int samples) {
    const rb::FeatureSet features(
        {rb::chapter01Feature(), rb::phongFeature(), rb::bvhFeature(),
         rb::reflectionFeature(), rb::refractionFeature(), rb::softShadowsFeature(),
         rb::glossyFeature()},
        "all");
    return rbchart::loadWorld(
        path, features, {{"glossy-sampler", sampler}, {"glossy-samples", std::to_string(samples)}});
}

/// Render at 128×96 with the given seed, one ray per pixel centre; `seconds` gets the CPU time.
rb::Image renderTimed(const rb::World& w, std::uint64_t seed, double& seconds) {
    return rbchart::renderTimed(w, kWidth, kHeight, seed, 1, seconds);
}

double meanSquaredError(const rb::Image& a, const rb::Image& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.data().size(); ++i) {
        const double d = double(a.data()[i]) - double(b.data()[i]);
        sum += d * d;
    }
    return sum / a.data().size();
}

/// The exact fraction of a Phong lobe (exponent n, axis θ from the normal) below the surface;
/// the same integral as tests/ch07_glossy.cpp's phongLostFraction.
double phongLostFraction(double n, double theta) {
    const double tStar = std::pow(std::sin(theta), n + 1);
    auto ring = [&](double t) {
        const double mu = std::pow(t, 1.0 / (n + 1));
        const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        if (sinAlpha <= 0.0) return 0.0;
        const double k = mu * std::cos(theta) / (sinAlpha * std::sin(theta));
        return k >= 1.0 ? 0.0 : std::acos(std::max(-1.0, k)) / kPi;
    };
    const int m = 200000;
    double sum = 0.0;
    for (int i = 0; i <= m; ++i) {
        const double s = double(i) / m;
        const double f = ring(tStar * (1.0 - s * s)) * 2.0 * tStar * s;
        sum += f * (i == 0 || i == m ? 1.0 : (i % 2 ? 4.0 : 2.0));
    }
    return sum / (3.0 * m);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: ch07_glossy_charts SCENE OUT_DIR\n");
        return 2;
    }
    const std::string scene = argv[1], out = argv[2];

    // ---- Equal time: RMSE against each sampler's own reference, against CPU time ----
    std::ofstream data(out + "/equal-time.dat");
    data << "# sampler N cpu_seconds rmse\n";
    std::map<std::string, double> efficiency;  // 1 / (MSE · time), averaged over N ≥ 4
    std::map<std::string, std::pair<double, double>> last;  // (time, RMSE) at N = 128
    for (const std::string sampler : {"fuzz", "lobe"}) {
        // The reference: two independent renders of 1024 directions. Their mean is the
        // reference; half their mean squared difference, halved again, is its own variance
        // (per pixel and channel), which is subtracted from every measured MSE.
        double t = 0.0;
        const auto refWorld = buildWorld(scene, sampler, 1024);
        const rb::Image a = renderTimed(*refWorld, 101, t);
        const rb::Image b = renderTimed(*refWorld, 202, t);
        const rb::Image reference = rbchart::meanImage(a, b);
        const double referenceVariance = meanSquaredError(a, b) / 4.0;
        double logEfficiency = 0.0;
        int points = 0;
        for (int n = 1; n <= 128; n *= 2) {
            const auto w = buildWorld(scene, sampler, n);
            double best = 1e300;
            rb::Image image(1, 1);
            for (int run = 0; run < 3; ++run) {
                double seconds = 0.0;
                image = renderTimed(*w, 7, seconds);
                best = std::min(best, seconds);
            }
            const double mse =
                std::max(0.0, meanSquaredError(image, reference) - referenceVariance);
            data << sampler << " " << n << " " << best << " " << std::sqrt(mse) << "\n";
            std::printf("%s N=%3d  %.3f s  RMSE %.5f\n", sampler.c_str(), n, best, std::sqrt(mse));
            last[sampler] = {best, std::sqrt(mse)};
            if (n >= 4) {
                logEfficiency += -std::log(mse * best);
                ++points;
            }
        }
        efficiency[sampler] = std::exp(logEfficiency / points);
        data << "\n\n";
    }
    // At equal time t, RMSE = 1/√(efficiency · t): the ratio of the samplers' RMSEs.
    const double ratio = std::sqrt(efficiency["fuzz"] / efficiency["lobe"]);
    {
        std::ofstream finding(out + "/finding.txt");
        // The cost of one direction, from the largest N (where fixed costs matter least).
        char text[600];
        std::snprintf(text, sizeof text,
                      "At equal CPU time the Phong lobe's RMSE is %.2f times the fuzz sphere's "
                      "(geometric mean over N = 4 to 128 directions, each sampler against its "
                      "own 2048-direction reference; at N = 128 the fuzz sphere took %.3f s and "
                      "the lobe %.3f s for RMSE %.4f and %.4f).",
                      ratio, last["fuzz"].first, last["lobe"].first, last["fuzz"].second,
                      last["lobe"].second);
        finding << text << "\n";
        std::printf("%s\n", text);
    }

    // ---- The two lobes' look: the chapter scene as it is (16 directions per glossy surface),
    // 192×144 with 8 jittered samples per pixel, fuzz | lobe ----
    double unused = 0.0;
    rbchart::sideBySide(
        rbchart::renderTimed(*buildWorld(scene, "fuzz", 16), 192, 144, 1, 8, unused),
        rbchart::renderTimed(*buildWorld(scene, "lobe", 16), 192, 144, 1, 8, unused),
        out + "/lobes.png");

    // ---- Energy lost below the surface near grazing ----
    std::ofstream grazing(out + "/grazing.dat");
    grazing << "# elevation_deg lost_fuzz(g) lost_lobe(g) exact_lobe(g), for g = 0.1 then 0.3\n";
    for (const double g : {0.1, 0.3}) {
        rb::Material m;
        m.params["glossiness"] = g;
        const rb::GlossyLobe fuzz(rb::LobeKind::Fuzz, 1), lobe(rb::LobeKind::Phong, 1);
        const rb::Vec3 normal(0, 0, 1);
        for (int e = 0; e <= 30; ++e) {
            const double elevation = e * kPi / 180.0;
            const rb::Vec3 axis(std::cos(elevation), 0.0, std::sin(elevation));
            const int count = 100000;
            int lostFuzz = 0, lostLobe = 0;
            rb::Sampler sampler(1, e, 0);
            for (int i = 0; i < count; ++i) {
                rb::Vec3 w;
                lostFuzz += !fuzz.sample(m, axis, normal, sampler, w);
                lostLobe += !lobe.sample(m, axis, normal, sampler, w);
            }
            const double n = rb::phongExponentFromFuzz(rb::fuzzFromGlossiness(g));
            grazing << e << " " << double(lostFuzz) / count << " " << double(lostLobe) / count
                    << " " << phongLostFraction(n, kPi / 2 - elevation) << "\n";
        }
        grazing << "\n\n";
    }

    // ---- The lobes' shapes ----
    std::ofstream shapes(out + "/lobe-shapes.dat");
    shapes << "# alpha_deg fuzz/fuzz(0) lobe/lobe(0), for g = 0.05, 0.15, 0.4\n";
    for (const double g : {0.05, 0.15, 0.4}) {
        const double f = rb::fuzzFromGlossiness(g), n = rb::phongExponentFromFuzz(f);
        for (int i = 0; i <= 600; ++i) {
            const double alpha = i * 30.0 / 600 * kPi / 180.0;
            shapes << alpha * 180.0 / kPi << " "
                   << rb::fuzzSpherePdf(f, std::cos(alpha)) / rb::fuzzSpherePdf(f, 1.0) << " "
                   << rb::phongLobePdf(n, std::cos(alpha)) / rb::phongLobePdf(n, 1.0) << "\n";
        }
        shapes << "\n\n";
    }
    return 0;
}
