// ch05_fresnel_bench: time per evaluation of the exact Fresnel reflectance and of Schlick's
// approximation. A benchmark, not a test: the numbers depend on the machine and its load.
//
// Each measurement evaluates one formula over 65,536 angles of incidence, uniform in angle
// from 0° to 90° and shuffled (so the total-internal-reflection branch is as unpredictable as
// in a render), 32 times over; it is repeated 21 times and the median, minimum and maximum
// nanoseconds per evaluation are reported. The formulas live in another translation unit
// (src/refraction/fresnel.cpp), so neither is inlined into the loop: both pay one call, as in
// the renderer. "loop only" is the same loop summing the cosines, to show what the loop costs.
//
// usage: ch05_fresnel_bench OUT_DIR
//   OUT_DIR/fresnel-time.dat   label, median, min, max (ns per evaluation)
//   OUT_DIR/time-finding.txt   the finding in one sentence
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "refraction/fresnel.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Timing {
    double median, min, max;
};

/// Median, min and max ns per evaluation of f over the cosines.
template <typename F>
Timing measure(const std::vector<double>& cosines, F f, double& sink) {
    constexpr int kRepeats = 21, kPasses = 32;
    std::vector<double> ns;
    for (int r = 0; r < kRepeats; ++r) {
        double sum = 0.0;
        const auto t0 = Clock::now();
        for (int pass = 0; pass < kPasses; ++pass)
            for (double c : cosines) sum += f(c);
        const auto t1 = Clock::now();
        sink += sum;
        ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() /
                     (double(kPasses) * cosines.size()));
    }
    std::sort(ns.begin(), ns.end());
    return {ns[ns.size() / 2], ns.front(), ns.back()};
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: ch05_fresnel_bench OUT_DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    // The angles: uniform in [0°, 90°], shuffled with a fixed seed.
    std::vector<double> cosines(65536);
    for (size_t i = 0; i < cosines.size(); ++i)
        cosines[i] = std::cos(0.5 * M_PI * i / (cosines.size() - 1));
    std::mt19937_64 engine(5);
    for (size_t i = cosines.size() - 1; i > 0; --i)
        std::swap(cosines[i], cosines[engine() % (i + 1)]);

    double sink = 0.0;
    struct Row {
        const char* label;
        Timing t;
    };
    const Row rows[] = {
        {"loop only", measure(
                          cosines, [](double c) { return c; }, sink)},
        {"exact, in", measure(
                          cosines, [](double c) { return rb::fresnelExact(c, 1.0, 1.5); }, sink)},
        {"Schlick, in",
         measure(
             cosines, [](double c) { return rb::fresnelSchlick(c, 1.0, 1.5); }, sink)},
        {"exact, out", measure(
                           cosines, [](double c) { return rb::fresnelExact(c, 1.5, 1.0); }, sink)},
        {"Schlick, out",
         measure(
             cosines, [](double c) { return rb::fresnelSchlick(c, 1.5, 1.0); }, sink)},
    };

    std::FILE* out = std::fopen((dir + "/fresnel-time.dat").c_str(), "w");
    if (!out) return 1;
    std::fprintf(out,
                 "# label  median_ns  min_ns  max_ns  (n = 1.5; in: 1 -> 1.5, out: 1.5 -> 1)\n");
    for (const Row& r : rows) {
        std::fprintf(out, "\"%s\" %.3f %.3f %.3f\n", r.label, r.t.median, r.t.min, r.t.max);
        std::printf("%-14s %7.2f ns  (min %.2f, max %.2f)\n", r.label, r.t.median, r.t.min,
                    r.t.max);
    }
    std::fclose(out);
    std::FILE* finding = std::fopen((dir + "/time-finding.txt").c_str(), "w");
    if (!finding) return 1;
    std::fprintf(finding,
                 "Schlick takes %.1f ns per evaluation going in and %.1f ns going out, against "
                 "%.1f and %.1f ns for the exact equations (%.1fx and %.1fx; the loop alone "
                 "costs %.1f ns).\n",
                 rows[2].t.median, rows[4].t.median, rows[1].t.median, rows[3].t.median,
                 rows[1].t.median / rows[2].t.median, rows[3].t.median / rows[4].t.median,
                 rows[0].t.median);
    std::fclose(finding);
    if (sink == 42.0) std::printf(" ");  // keep the sums alive
    return 0;
}
