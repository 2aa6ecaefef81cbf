#include "core/render.h"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <vector>

namespace rb {

namespace {

/// Draws "[#####     ] 52% ETA 3.1 s" on stderr. Only thread 0 draws, so no lock is needed.
class ProgressBar {
  public:
    ProgressBar(bool enabled, int total) : enabled_(enabled), total_(total) {}
    /// Record one finished row, and redraw now and then.
    void rowDone() {
        if (!enabled_) return;
        const int done = ++done_;
        if (omp_get_thread_num() != 0) return;
        const double elapsed = seconds();
        if (elapsed - lastDraw_ < 0.2 && done < total_) return;
        lastDraw_ = elapsed;
        draw(done, elapsed);
    }
    /// Clear the bar.
    void finish() {
        if (enabled_) std::fprintf(stderr, "\r%60s\r", "");
    }

  private:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    void draw(int done, double elapsed) const {
        const double fraction = static_cast<double>(done) / total_;
        const int filled = static_cast<int>(30 * fraction);
        const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
        std::fprintf(stderr, "\r[%-30s] %3d%% ETA %.1f s ", std::string(filled, '#').c_str(),
                     static_cast<int>(100 * fraction), eta);
    }
    bool enabled_;
    int total_;
    std::atomic<int> done_{0};
    double lastDraw_ = 0.0;  // touched by thread 0 only
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

// [render-loop]
Image render(const Scene& scene, const Pipeline& pipeline, const PinholeCamera& camera, int width,
             int height, const RenderSettings& settings, RayCounters& counters) {
    Image image(width, height);
    const Integrator integrator(scene, pipeline);
    const int threads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
    std::vector<RayCounters> perThread(threads);
    ProgressBar progress(settings.progress, height);
    const int spp = std::max(1, settings.samplesPerPixel);

    // Rows go to threads dynamically. Nothing a pixel computes depends on which thread runs
    // it: its random numbers come from (seed, pixel, sample), so any schedule gives the same
    // image.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int y = 0; y < height; ++y) {
        RayCounters& rays = perThread[omp_get_thread_num()];
        for (int x = 0; x < width; ++x) {
            const std::uint64_t pixelIndex = static_cast<std::uint64_t>(y) * width + x;
            Colour sum(0.0);
            for (int s = 0; s < spp; ++s) {
                Sampler sampler(settings.seed, pixelIndex, s);
                // One sample: the pixel centre (A4), or a uniformly jittered position.
                const Vec2 offset = spp == 1 ? Vec2(0.5) : sampler.next2D();
                const Ray ray = camera.generateRay(x + offset.x, y + offset.y);
                rays.add(RayKind::Camera);
                sum += integrator.trace(ray, sampler, rays, 0);
            }
            image.set(x, y, sum / static_cast<double>(spp));
        }
        progress.rowDone();
    }
    progress.finish();
    for (const RayCounters& c : perThread) counters.merge(c);
    return image;
}
// [render-loop]

}  // namespace rb
