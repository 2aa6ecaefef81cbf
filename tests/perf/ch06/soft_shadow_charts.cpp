// Chapter 6's chart data (make charts): how fast soft-shadow error falls, independent against
// stratified sampling of the area lights.
//
//   ch06_soft_shadow_charts CHAPTER_SCENE HIGHLIGHT_SCENE OUT_DIR
//
// writes into OUT_DIR:
//   convergence.dat  strategy, samples per axis n, samples per light N = n², render CPU seconds,
//                    RMSE against the converged render; index 0 independent, index 1 stratified
//   finding.txt      one sentence with the numbers, for the chapter page
//   hard-vs-soft.png the chapter scene with point lights | with area lights (256×192 each)
//   highlight.png    the highlight close-up, point lights | area lights (256×192 each)
//
// The error is measured on the chapter scene at 128×96, one ray through each pixel centre, so
// the light sampling is the only randomness. The reference is the mean of two stratified
// renders of 64 × 64 samples per light with different seeds; a quarter of their mean squared
// difference estimates the reference's own variance, which is subtracted from every measured
// MSE. Error is in displayed units (each channel clamped to [0, 1], as the PNG shows it). Time
// is the process's CPU time for the render (both threads), the fastest of 3 runs: a busy
// shared machine disturbs it less than wall-clock time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "chart_helpers.h"
#include "scene/chapter_features.h"
#include "phong/phong.h"
#include "bvh/bvh_aggregate.h"
#include "core/image.h"
#include "soft_shadows/soft_shadows.h"

using rbchart::renderTimed;
using rbchart::sideBySide;

namespace {

constexpr int kWidth = 128, kHeight = 96;

/// The scene file `path` built as `rt` builds it, with chapters 1–3 and 6 switched on by `spec`
/// and chapter 6's command-line options.
std::unique_ptr<rb::World> buildWorld(const std::string& path,
                                      const std::map<std::string, std::string>& cli,
                                      const std::string& spec = "all") {
    const rb::FeatureSet features({rb::chapter01Feature(), rb::phongFeature(),
                                   rb::bvhFeature(), rb::softShadowsFeature()},
                                  spec);
    return rbchart::loadWorld(path, features, cli);
}

/// Mean squared difference of displayed values (each channel clamped to [0, 1]).
double meanSquaredError(const rb::Image& a, const rb::Image& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.data().size(); ++i) {
        const double d =
            std::clamp(double(a.data()[i]), 0.0, 1.0) - std::clamp(double(b.data()[i]), 0.0, 1.0);
        sum += d * d;
    }
    return sum / a.data().size();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr,
                     "usage: ch06_soft_shadow_charts CHAPTER_SCENE HIGHLIGHT_SCENE OUT_DIR\n");
        return 2;
    }
    const std::string scene = argv[1], highlightScene = argv[2], out = argv[3];

    // ---- The reference: two 64 × 64 stratified renders, and their own variance ----
    double t = 0.0;
    const auto refWorld = buildWorld(scene, {{"light-samples", "64"}});
    const rb::Image a = renderTimed(*refWorld, kWidth, kHeight, 101, 1, t);
    const rb::Image b = renderTimed(*refWorld, kWidth, kHeight, 202, 1, t);
    const rb::Image reference = rbchart::meanImage(a, b);
    const double referenceVariance = meanSquaredError(a, b) / 4.0;
    std::printf("reference: 2 x 64x64 samples per light, %.1f s each, RMSE of the mean %.6f\n", t,
                std::sqrt(referenceVariance));

    // ---- RMSE and CPU time against samples per light, for both strategies ----
    std::ofstream data(out + "/convergence.dat");
    data << "# strategy n N=n^2 cpu_seconds rmse\n";
    const std::vector<int> perAxis = {1, 2, 3, 4, 6, 8, 12, 16};
    std::map<std::string, std::vector<double>> rmse, seconds;
    for (const std::string strategy : {"independent", "stratified"}) {
        for (int n : perAxis) {
            const auto w = buildWorld(
                scene, {{"light-sampling", strategy}, {"light-samples", std::to_string(n)}});
            double best = 1e300;
            rb::Image image(1, 1);
            for (int run = 0; run < 3; ++run) {
                double s = 0.0;
                image = renderTimed(*w, kWidth, kHeight, 7, 1, s);
                best = std::min(best, s);
            }
            const double e =
                std::sqrt(std::max(0.0, meanSquaredError(image, reference) - referenceVariance));
            data << strategy << " " << n << " " << n * n << " " << best << " " << e << "\n";
            std::printf("%-11s n=%2d N=%3d  %.3f s  RMSE %.5f\n", strategy.c_str(), n, n * n, best,
                        e);
            rmse[strategy].push_back(e);
            seconds[strategy].push_back(best);
        }
        data << "\n\n";
    }

    // ---- The finding: the log-log slopes, and the equal-error speed-up at 16 × 16 ----
    const auto slope = [&](const std::vector<double>& y) {
        double xBar = 0, yBar = 0, sxx = 0, sxy = 0;
        const size_t m = perAxis.size();
        for (size_t i = 0; i < m; ++i) {
            xBar += std::log(double(perAxis[i] * perAxis[i])) / m;
            yBar += std::log(y[i]) / m;
        }
        for (size_t i = 0; i < m; ++i) {
            const double dx = std::log(double(perAxis[i] * perAxis[i])) - xBar;
            sxx += dx * dx;
            sxy += dx * (std::log(y[i]) - yBar);
        }
        return sxy / sxx;
    };
    const double slopeInd = slope(rmse["independent"]), slopeStr = slope(rmse["stratified"]);
    // Samples independent sampling would need for the stratified 16 × 16 error, from its own
    // fitted line through the last point: N = 256 · (e_ind(256) / e_str(256))^(1 / −slope).
    const double eInd = rmse["independent"].back(), eStr = rmse["stratified"].back();
    const double samplesNeeded = 256.0 * std::pow(eInd / eStr, -1.0 / slopeInd);
    {
        char text[800];
        std::snprintf(text, sizeof text,
                      "On the chapter scene the RMSE of independent light samples falls with "
                      "slope %.2f against samples per light (the 1/sqrt(N) law) and that of "
                      "stratified samples with slope %.2f; at 16 x 16 samples per light, in the "
                      "same %.2f s, stratified sampling's RMSE is %.4f against %.4f; "
                      "independent sampling would need about %.0f times as many samples (and as "
                      "much time) to match it, extrapolating its own line.",
                      slopeInd, slopeStr, seconds["stratified"].back(), eStr, eInd,
                      samplesNeeded / 256.0);
        std::ofstream(out + "/finding.txt") << text << "\n";
        std::printf("%s\n", text);
    }

    // ---- The look: point lights | area lights, for the scene and the highlight close-up ----
    for (const auto& [path, file, spp] :
         {std::tuple<std::string, std::string, int>{scene, "hard-vs-soft.png", 4},
          {highlightScene, "highlight.png", 4}}) {
        const auto hard = buildWorld(path, {}, "all,-soft_shadows");
        const auto soft = buildWorld(path, {{"light-samples", "16"}});
        double s = 0.0;
        sideBySide(renderTimed(*hard, 256, 192, 1, spp, s), renderTimed(*soft, 256, 192, 1, spp, s),
                   out + "/" + file);
    }
    return 0;
}
