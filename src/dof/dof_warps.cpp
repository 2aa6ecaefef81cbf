/// \file
/// Chapter 13's samplers in the sampling lab: Shirley and Chiu's concentric disk (exercise
/// 13.2), and where the thin lens starts its rays (exercises 13.1 and 13.3: ThinLens::generate,
/// which pairs lens strata with the pixel's rays), each compared with its stated density.
#include "core/camera.h"
#include "core/sampler.h"
#include "dof/lens_sampling.h"
#include "dof/thin_lens.h"
#include "lab/warp.h"

namespace rb {

namespace {

Warp concentricDiskWarp() {
    Warp w;
    w.name = "concentric-disk";
    w.chapter = 13;
    w.title = "Shirley and Chiu's concentric map of the square onto the unit disk: pdf 1/π";
    w.exercise = "13.2";
    w.setup = [](const std::map<std::string, double>&) {
        WarpSetup s;
        s.domain = {-1.0, 1.0, -1.0, 1.0, "x", "y"};
        s.caption = "the unit disk in the square [-1, 1]²";
        s.draw = [](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawEach(count, seed, 130, points,
                     [](Sampler& sampler) { return concentricDisk(sampler.next2D()); });
        };
        s.pdf = [](const Vec2& p) { return concentricDiskPdf(p); };
        return s;
    };
    return w;
}

Warp thinLensWarp() {
    Warp w;
    w.name = "thin-lens";
    w.chapter = 13;
    w.title =
        "where the thin lens starts a pixel's rays: uniform over the aperture, "
        "pdf 1/(π r²) (disk) or 1/a² (square)";
    w.exercise = "13.1, 13.3";
    w.parameters = {{"aperture", 0.5, 1e-3, 1e3, "the disk's diameter, or the square's side"},
                    {"samples", 16, 1, 1024, "lens samples per pixel (one stratum each)"},
                    {"square", 0, 0, 1, "1: seed 001's square aperture; 0: the disk"}};
    w.setup = [](const std::map<std::string, double>& v) {
        ThinLensSettings lens;
        lens.aperture = v.at("aperture");
        lens.focusDistance = 5.0;
        lens.samples = static_cast<int>(v.at("samples"));
        lens.shape = v.at("square") != 0.0 ? ApertureShape::Square : ApertureShape::Disk;
        const double r = 0.5 * lens.aperture;
        WarpSetup s;
        s.domain = {-r, r, -r, r, "along the camera's right", "along the camera's up"};
        s.caption = std::string(lens.shape == ApertureShape::Disk ? "disk" : "square") +
                    " aperture " + warpNumber(lens.aperture) + ", " + std::to_string(lens.samples) +
                    " rays per pixel";
        s.draw = [lens](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            // A camera looking along a skew direction, so the lens frame is not the world's.
            const int width = 64, height = 48;
            const PinholeCamera camera({{1.0, 2.0, 3.0}, {0.3, -0.2, -1.0}, {0.0, 1.0, 0.0}, 50.0},
                                       width, height);
            const ThinLens thinLens(lens);
            const std::uint64_t pixels = width * height;
            for (std::uint64_t q = 0; q * lens.samples < count; ++q) {
                const std::uint64_t pixel = q % pixels;
                const Vec2 film(pixel % width + 0.5, pixel / width + 0.5);
                for (int k = 0; k < lens.samples; ++k) {
                    // Pixel q's k-th ray, with q's own key (q may exceed the image's pixels).
                    Sampler sampler(seed, q, k);
                    const Ray ray =
                        thinLens.generate(camera, film, {seed, q, k, lens.samples}, sampler);
                    const Vec3 offset = ray.o - camera.eye();
                    points.push_back(
                        {glm::dot(offset, camera.right()), glm::dot(offset, camera.upVector())});
                }
            }
        };
        s.pdf = [lens, r](const Vec2& p) {
            return lens.shape == ApertureShape::Disk ? concentricDiskPdf(p / r) / (r * r)
                                                     : squareAperturePdf(p / r) / (r * r);
        };
        return s;
    };
    return w;
}

}  // namespace

/// Chapter 13's samplers for ./rt --warptest.
std::vector<Warp> dofWarps() {
    return {concentricDiskWarp(), thinLensWarp()};
}

}  // namespace rb
