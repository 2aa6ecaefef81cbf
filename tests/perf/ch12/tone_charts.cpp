// Chapter 12's chart data (make charts).
//
//   ch12_tone_charts SCENE OUT_DIR
//       renders the scene's film once (at its own size, as rt --features=all would), then
//       writes to OUT_DIR
//       side-by-side.png  the film clipped (none), through the global and the local operator
//       measures.dat      per operator: burnt %, channel-clipped %, crushed %, edges kept %
//                         (all, bright, dark)
//       bars.dat          the same transposed for gnuplot's histogram: one row per measure
//       finding.txt       one sentence with the numbers, for the chapter page
//
// The measures are taken on the 8-bit images rt would write (sRGB on for global and local,
// off for the clipped image, as the course writes it):
//   burnt     a pixel with every channel at 255: white, whatever the film held;
//   clipped   a pixel with some channel at 255: its hue is lost (a saturated colour whose
//             luminance fits can still overflow in one channel);
//   crushed   a pixel with every channel at 2 or below: black;
//   edges     pairs of neighbouring pixels whose film luminances differ by more than 10%
//             (a contrast the eye sees); one is kept when the written luma of the two differs
//             by 2 levels or more. "Bright" pairs have film luminance above 1 on both sides (the
//             sunlit floor, the window), "dark" ones below 0.1 (the room in shade).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "adaptive_aa/adaptive_aa.h"
#include "bvh/bvh_aggregate.h"
#include "chart_helpers.h"
#include "core/image.h"
#include "glossy/glossy.h"
#include "phong/phong.h"
#include "reflection/reflection.h"
#include "refraction/refraction.h"
#include "scene/chapter_features.h"
#include "soft_shadows/soft_shadows.h"
#include "tone_map/reinhard.h"
#include "tone_map/tone_map.h"

namespace {

/// What one tone map keeps of the film.
struct Measures {
    double burnt = 0, clipped = 0, crushed = 0;           ///< Shares of pixels, %.
    double edgesAll = 0, edgesBright = 0, edgesDark = 0;  ///< Shares of visible edges kept, %.
};

/// The luma of 8-bit pixel p (Rec. 709 weights on the written values).
double luma(const std::vector<unsigned char>& bytes, std::size_t p) {
    return 0.2126 * bytes[3 * p] + 0.7152 * bytes[3 * p + 1] + 0.0722 * bytes[3 * p + 2];
}

Measures measure(const rb::Image& film, const rb::Image& shown) {
    const std::vector<unsigned char> bytes = rb::toBytes(shown);
    const int w = film.width(), h = film.height();
    const std::size_t n = static_cast<std::size_t>(w) * h;
    Measures m;
    for (std::size_t p = 0; p < n; ++p) {
        const unsigned char* c = &bytes[3 * p];
        if (std::min({c[0], c[1], c[2]}) == 255) m.burnt += 1;
        if (std::max({c[0], c[1], c[2]}) == 255) m.clipped += 1;
        if (std::max({c[0], c[1], c[2]}) <= 2) m.crushed += 1;
    }
    m.burnt *= 100.0 / n;
    m.clipped *= 100.0 / n;
    m.crushed *= 100.0 / n;
    // Count the visible edges of the film, and those the image still shows.
    double all = 0, allKept = 0, bright = 0, brightKept = 0, dark = 0, darkKept = 0;
    const auto pair = [&](std::size_t p, std::size_t q) {
        const double a = rb::luminance(film.get(p % w, p / w));
        const double b = rb::luminance(film.get(q % w, q / w));
        const double lo = std::min(a, b), hi = std::max(a, b);
        if (!(hi > 1.1 * lo)) return;
        const bool kept = std::abs(luma(bytes, p) - luma(bytes, q)) >= 2.0;
        all += 1;
        allKept += kept;
        if (lo > 1.0) bright += 1, brightKept += kept;
        if (hi < 0.1) dark += 1, darkKept += kept;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * w + x;
            if (x + 1 < w) pair(p, p + 1);
            if (y + 1 < h) pair(p, p + w);
        }
    m.edgesAll = 100.0 * allKept / std::max(all, 1.0);
    m.edgesBright = 100.0 * brightKept / std::max(bright, 1.0);
    m.edgesDark = 100.0 * darkKept / std::max(dark, 1.0);
    return m;
}

/// Three images of one size side by side, 4 white pixels apart, written as a PNG.
void threeSideBySide(const std::vector<rb::Image>& images, const std::string& path) {
    const int w = images[0].width(), h = images[0].height(), gap = 4;
    rb::Image all(3 * w + 2 * gap, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < all.width(); ++x) {
            const int k = x / (w + gap), u = x % (w + gap);
            all.set(x, y, u < w ? images[k].get(u, y) : rb::Colour(1.0));
        }
    rb::writePng(all, path);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: ch12_tone_charts SCENE OUT_DIR\n");
        return 2;
    }
    const std::string scene = argv[1], out = argv[2];
    // Render the film with the scene's own settings except the tone map, which runs here.
    const rb::FeatureSet features(
        {rb::chapter01Feature(), rb::phongFeature(), rb::bvhFeature(), rb::reflectionFeature(),
         rb::refractionFeature(), rb::softShadowsFeature(), rb::glossyFeature(),
         rb::adaptiveAaFeature(), rb::toneMapFeature()},
        "all");
    const auto world = rbchart::loadWorld(scene, features);
    double seconds = 0;
    const int w = world->source.job.width, h = world->source.job.height;
    const rb::Image film = rbchart::renderTimed(*world, w, h, 1, 1, seconds);
    double lo = 1e300, hi = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double L = rb::luminance(film.get(x, y));
            if (L > 0) lo = std::min(lo, L);
            hi = std::max(hi, L);
        }

    const char* names[] = {"clipped", "global", "local"};
    std::vector<rb::Image> shown;
    std::vector<Measures> measures;
    for (int k = 0; k < 3; ++k) {
        rb::ToneMapSettings s;
        s.op = static_cast<rb::ToneOperator>(k);
        s.srgb = k != 0;
        rb::Image image = film;
        rb::toneMap(image, s);
        measures.push_back(measure(film, image));
        shown.push_back(std::move(image));
    }
    threeSideBySide(shown, out + "/side-by-side.png");
    std::ofstream data(out + "/measures.dat");
    data << "# operator burnt% channel-clipped% crushed% edges-kept-all% edges-kept-bright% "
            "edges-kept-dark%\n";
    for (int k = 0; k < 3; ++k)
        data << names[k] << ' ' << measures[k].burnt << ' ' << measures[k].clipped << ' '
             << measures[k].crushed << ' ' << measures[k].edgesAll << ' ' << measures[k].edgesBright
             << ' ' << measures[k].edgesDark << '\n';
    std::ofstream bars(out + "/bars.dat");
    bars << "# measure clipped global local\n";
    const auto row = [&](const char* label, double Measures::*field) {
        bars << '"' << label << '"';
        for (const Measures& m : measures) bars << ' ' << m.*field;
        bars << '\n';
    };
    row("burnt white", &Measures::burnt);
    row("1 channel clipped", &Measures::clipped);
    row("all edges kept", &Measures::edgesAll);
    row("bright edges kept", &Measures::edgesBright);
    row("shade edges kept", &Measures::edgesDark);
    char finding[1024];
    std::snprintf(
        finding, sizeof finding,
        "On the chapter scene (%dx%d, film luminance %.3g to %.3g, %.0f:1), clipping burns %.1f%% "
        "of the pixels to white and keeps %.0f%% of the visible edges (%.0f%% among bright "
        "pixels, %.0f%% in the shade); Reinhard's global operator burns %.1f%% and keeps %.0f%% "
        "(%.0f%% bright, %.0f%% shade); the local operator burns %.1f%% and keeps %.0f%% "
        "(%.0f%% bright, %.0f%% shade); in one channel the three clip %.0f%%, %.0f%% and %.0f%% "
        "of the pixels, the sunlit floor's orange and the sky's blue overflowing where their "
        "luminance fits.\n",
        w, h, lo, hi, hi / lo, measures[0].burnt, measures[0].edgesAll, measures[0].edgesBright,
        measures[0].edgesDark, measures[1].burnt, measures[1].edgesAll, measures[1].edgesBright,
        measures[1].edgesDark, measures[2].burnt, measures[2].edgesAll, measures[2].edgesBright,
        measures[2].edgesDark, measures[0].clipped, measures[1].clipped, measures[2].clipped);
    std::ofstream(out + "/finding.txt") << finding;
    std::fputs(finding, stdout);
    return 0;
}
