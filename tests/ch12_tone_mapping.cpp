/// \file
/// Chapter 12 tests: tone mapping.
///
/// Chapter 12 claims that a film of any dynamic range can be shown on a display that shows
/// [0, 1], keeping what matters: Reinhard's global curve L / (1 + L) squeezes every luminance
/// into [0, 1) without clipping, keeps dark values as they are (slope 1 at 0) and, with the
/// factor 1 + L / L_white², sends L_white exactly to white; the log-average luminance (the key)
/// fixes the scale, so the picture no longer depends on how bright the film happens to be;
/// the local operator picks for each pixel the largest neighbourhood with no edge in it and
/// divides by that neighbourhood's brightness, so it keeps detail inside bright and dark
/// regions that the global curve flattens; sRGB encoding is the standard's piecewise curve.
/// The tests check each formula against its closed form or a hand computation, the scale
/// selection on images whose edges are known, the .hdr file against the film it came from,
/// and, as stability cases, images that break naive code (black, one bright pixel, NaN,
/// infinity, negative values). Nothing here is random. End-to-end tests check that a scene
/// asks for the tone map through the scene or the command line, and that a scene which does
/// not ask gets no post-process at all (its output stays what chapter 8 writes).
#include <stb_image.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/post_process.h"
#include "test_helpers.h"
#include "tone_map/hdr_output.h"
#include "tone_map/reinhard.h"
#include "tone_map/srgb.h"
#include "tone_map/tone_map.h"

using Catch::Contains;
using rb::Colour;

namespace {

/// A width × height grey image whose pixel p has luminance values[p] (R = G = B, so the
/// luminance is the value itself).
rb::Image greyImage(int width, int height, const std::vector<double>& values) {
    rb::Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.set(x, y, Colour(values[y * width + x]));
    return image;
}

/// The settings of one operator with sRGB off, so the results are the operator's own.
rb::ToneMapSettings plain(rb::ToneOperator op, double white = 0.0) {
    rb::ToneMapSettings s;
    s.op = op;
    s.white = white;
    return s;
}

/// True when every channel is finite and in [0, 1].
bool displayable(const rb::Image& image) {
    return std::all_of(image.data().begin(), image.data().end(),
                       [](float c) { return std::isfinite(c) && c >= 0.0f && c <= 1.0f; });
}

/// The tone_map post-process a world installed, or null.
const rb::ToneMapper* installed(const rb::World& w) {
    return dynamic_cast<const rb::ToneMapper*>(w.pipeline.postProcess.get());
}

/// A small scene: a grey ball under one light.
const std::string kBall =
    "root = gr.node('root')\n"
    "local s = gr.sphere('s')\n"
    "s:set_material(gr.material({0.7, 0.7, 0.7}, {0.3, 0.3, 0.3}, 20))\n"
    "root:add_child(s)\n"
    "gr.render(root, 'out.png', 24, 18, {0, 0, 6}, {0, 0, -1}, {0, 1, 0}, 40, {0.1, 0.1, 0.1},"
    " {gr.light({3, 3, 6}, {8, 8, 8}, {1, 0, 0})})\n";

/// The world of `lua` in a chapter-12 build with `spec` switched on.
std::unique_ptr<rb::World> world(const std::string& lua,
                                 const std::map<std::string, std::string>& cli = {},
                                 const std::string& spec = "all") {
    return rbtest::worldFromLua(lua, rbtest::chapters(12, spec), cli);
}

}  // namespace

// ---- The global operator ----------------------------------------------------------------------

// [ch12-global-limits]
SCENARIO("L / (1 + L) keeps dark values, halves L = 1 and never reaches white", "[ch12][ex12.2]") {
    const double inf = std::numeric_limits<double>::infinity();
    GIVEN("the global operator without L_white (L_white = infinity)") {
        THEN("0 stays 0 and small values pass almost unchanged (the slope at 0 is 1)") {
            // Source: L / (1 + L) = L − L² + O(L³).
            CHECK(rb::reinhardGlobal(0.0, inf) == 0.0);
            CHECK(rb::reinhardGlobal(1e-6, inf) == Approx(1e-6 - 1e-12).epsilon(1e-9));
        }
        THEN("L = 1 gives one half, and L = 10^12 stays just below 1") {
            CHECK(rb::reinhardGlobal(1.0, inf) == 0.5);
            CHECK(rb::reinhardGlobal(1e12, inf) < 1.0);
            CHECK(rb::reinhardGlobal(1e12, inf) == Approx(1.0 - 1e-12).epsilon(1e-15));
        }
        THEN("it is strictly increasing from 10^-6 to 10^12") {
            double previous = rb::reinhardGlobal(1e-6, inf);
            for (double e = -5.9; e <= 12.0; e += 0.1) {
                const double next = rb::reinhardGlobal(std::pow(10.0, e), inf);
                CHECK(next > previous);
                previous = next;
            }
        }
    }
}
// [ch12-global-limits]

// [ch12-white]
SCENARIO("L_white maps to exactly 1, and only what is brighter burns out", "[ch12][ex12.2]") {
    for (const double Lwhite : {0.5, 1.0, 2.0, 10.0, 1000.0}) {
        GIVEN("L_white = " + std::to_string(Lwhite)) {
            THEN("L_white itself becomes 1, below it less, above it more") {
                // Source: L_white (1 + L_white / L_white²) / (1 + L_white)
                //       = (L_white + 1) / (1 + L_white) = 1.
                CHECK(rb::reinhardGlobal(Lwhite, Lwhite) == Approx(1.0).epsilon(1e-14));
                CHECK(rb::reinhardGlobal(0.9 * Lwhite, Lwhite) < 1.0);
                CHECK(rb::reinhardGlobal(1.1 * Lwhite, Lwhite) > 1.0);
            }
            THEN("the curve is still strictly increasing") {
                double previous = 0.0;
                for (double L = 0.01; L < 4.0 * Lwhite; L *= 1.2) {
                    const double next = rb::reinhardGlobal(L, Lwhite);
                    CHECK(next > previous);
                    previous = next;
                }
            }
            THEN("it lies above L / (1 + L), by the factor 1 + L / L_white²") {
                const double L = 0.3 * Lwhite;
                CHECK(rb::reinhardGlobal(L, Lwhite) ==
                      Approx(L / (1.0 + L) * (1.0 + L / (Lwhite * Lwhite))).epsilon(1e-14));
            }
        }
    }
}
// [ch12-white]

// ---- The key --------------------------------------------------------------------------------

// [ch12-key]
SCENARIO("the log-average luminance is the geometric mean, as worked out by hand",
         "[ch12][ex12.1]") {
    GIVEN("four luminances 1, 2, 4 and 8") {
        const std::vector<double> Lw = {1.0, 2.0, 4.0, 8.0};
        THEN("with δ = 0 it is (1 · 2 · 4 · 8)^(1/4) = 64^(1/4) = 2√2") {
            // Source: exp(mean(log L)) = (Π L)^(1/N); 64^(1/4) = 2^(6/4) = 2√2 = 2.8284271247.
            CHECK(rb::logAverageLuminance(Lw, 0.0) == Approx(2.0 * std::sqrt(2.0)).epsilon(1e-14));
        }
        THEN("with δ = 10^-4 it is 2√2 · (1 + δ/4 · (1 + 1/2 + 1/4 + 1/8)) to first order") {
            // Source: log(L + δ) = log L + δ / L + O(δ²), so the mean of the logarithms grows
            // by δ/4 · Σ 1/L = δ/4 · 1.875, and the exponential by that factor: 2.8285597.
            const double expected = 2.0 * std::sqrt(2.0) * (1.0 + 1e-4 / 4.0 * 1.875);
            CHECK(rb::logAverageLuminance(Lw, 1e-4) == Approx(expected).epsilon(1e-8));
        }
    }
}

SCENARIO("the global operator scales the log-average luminance to the key",
         "[ch12][ex12.1][ex12.2]") {
    GIVEN("a film of three grey pixels 1, 2 and 4 (log average 2)") {
        const rb::Image film = greyImage(3, 1, {1.0, 2.0, 4.0});
        WHEN("it is tone mapped by the global operator with key 0.18 and no L_white") {
            rb::Image out = film;
            rb::toneMap(out, plain(rb::ToneOperator::Global, -1.0));
            THEN("the middle pixel is scaled to the key, 0.18, and shown as 0.18 / 1.18") {
                // Source: L = a / L̄w · Lw = 0.18 / 2 · 2 = 0.18 (δ moves L̄w by 6e-5 relative).
                CHECK(out.get(1, 0).g == Approx(0.18 / 1.18).epsilon(1e-4));
                CHECK(out.get(0, 0).g == Approx(0.09 / 1.09).epsilon(1e-4));
                CHECK(out.get(2, 0).g == Approx(0.36 / 1.36).epsilon(1e-4));
            }
        }
    }
}
// [ch12-key]

SCENARIO("the key makes the picture independent of how bright the film is",
         "[ch12][ex12.1][ex12.3]") {
    GIVEN("a film from 1 to 8000 and the same film 16 times brighter") {
        std::vector<double> values;
        for (int i = 0; i < 40; ++i) values.push_back(std::pow(10.0, i / 10.0));
        const rb::Image dim = greyImage(8, 5, values);
        for (double& v : values) v *= 16.0;
        const rb::Image bright = greyImage(8, 5, values);
        for (const auto op : {rb::ToneOperator::Global, rb::ToneOperator::Local}) {
            WHEN("both go through the " +
                 std::string(rb::kToneOperatorNames[static_cast<int>(op)]) + " operator") {
                rb::Image a = dim, b = bright;
                rb::toneMap(a, plain(op));
                rb::toneMap(b, plain(op));
                THEN("they look the same, up to the δ of the log average") {
                    // Source: L = a Lw / L̄w is unchanged when Lw is scaled, except that
                    // log(δ + Lw) is not log Lw: the key moves by at most δ / min Lw = 1e-4.
                    for (std::size_t i = 0; i < a.data().size(); ++i)
                        CHECK(a.data()[i] == Approx(b.data()[i]).margin(1e-4));
                }
            }
        }
        WHEN("the global operator runs with exposure +2 stops, and with the key times 4") {
            rb::Image a = dim, b = dim;
            rb::ToneMapSettings s = plain(rb::ToneOperator::Global);
            s.exposure = 2.0;
            rb::toneMap(a, s);
            s.exposure = 0.0;
            s.key = 0.72;
            rb::toneMap(b, s);
            THEN("exposure is the key by another name: the images agree") {
                for (std::size_t i = 0; i < a.data().size(); ++i)
                    CHECK(a.data()[i] == Approx(b.data()[i]).margin(1e-6));
            }
        }
    }
}

SCENARIO("exposure alone multiplies the film by 2^EV, then clips", "[ch12]") {
    GIVEN("grey pixels 0.1, 0.3 and 0.7, exposure +1 and no operator") {
        rb::Image film = greyImage(3, 1, {0.1, 0.3, 0.7});
        rb::ToneMapSettings s;
        s.exposure = 1.0;
        rb::toneMap(film, s);
        THEN("they become 0.2, 0.6 and 1 (1.4 clipped)") {
            CHECK(film.get(0, 0).r == Approx(0.2).epsilon(1e-6));
            CHECK(film.get(1, 0).r == Approx(0.6).epsilon(1e-6));
            CHECK(film.get(2, 0).r == 1.0f);
        }
    }
}

// ---- sRGB -----------------------------------------------------------------------------------

// [ch12-srgb]
SCENARIO("sRGB encoding follows the standard's two pieces, joined at 0.0031308", "[ch12][ex12.4]") {
    THEN("black and white stay, and linear 0.5 becomes 0.7354") {
        // Source: IEC 61966-2-1: 1.055 · 0.5^(1/2.4) − 0.055 = 0.735356983.
        CHECK(rb::srgbEncode(0.0) == 0.0);
        CHECK(rb::srgbEncode(1.0) == Approx(1.0).epsilon(1e-12));
        CHECK(rb::srgbEncode(0.5) == Approx(0.7353569830524495).epsilon(1e-12));
    }
    THEN("below the knee it is the straight line 12.92 c") {
        CHECK(rb::srgbEncode(0.001) == Approx(0.01292).epsilon(1e-12));
        CHECK(rb::srgbEncode(0.0031308) == Approx(0.040449936).epsilon(1e-12));
    }
    THEN("the two pieces meet at the knee (to 3e-8) and the curve rises throughout") {
        // Source: 1.055 · 0.0031308^(1/2.4) − 0.055 = 0.0404499075, 12.92 · 0.0031308 =
        // 0.0404499360.
        CHECK(rb::srgbEncode(0.0031309) == Approx(0.040449936).margin(3e-5));
        double previous = -1.0;
        for (double c = 0.0; c <= 1.0; c += 1e-4) {
            CHECK(rb::srgbEncode(c) > previous);
            previous = rb::srgbEncode(c);
        }
    }
    THEN("values outside [0, 1] are clamped first") {
        CHECK(rb::srgbEncode(-0.5) == 0.0);
        CHECK(rb::srgbEncode(7.0) == Approx(1.0).epsilon(1e-12));
    }
}
// [ch12-srgb]

// ---- The local operator ---------------------------------------------------------------------

// [ch12-local-flat]
SCENARIO("on a flat image the local operator chooses the largest scale and equals L / (1 + L)",
         "[ch12][ex12.3]") {
    GIVEN("a 40 × 30 image of constant scaled luminance L = 3") {
        const std::vector<double> L(40 * 30, 3.0);
        rb::LocalOperatorSettings s;
        std::vector<int> scale;
        const std::vector<double> V1 = rb::localAdaptation(L, 40, 30, s, &scale);
        const std::vector<double> Ld = rb::reinhardLocal(L, 40, 30, s);
        THEN("no centre differs from its surround: every pixel takes the last scale, 1.6^7") {
            CHECK(
                std::all_of(scale.begin(), scale.end(), [&](int m) { return m == s.scales - 1; }));
        }
        THEN("V1 = L (the blur of a constant is the constant) and L_d = 3 / 4") {
            for (std::size_t p = 0; p < L.size(); ++p) {
                CHECK(V1[p] == Approx(3.0).epsilon(1e-12));
                CHECK(Ld[p] == Approx(0.75).epsilon(1e-12));
            }
        }
    }
}
// [ch12-local-flat]

// [ch12-local-edge]
SCENARIO("the local operator stops growing a pixel's neighbourhood at an edge", "[ch12][ex12.3]") {
    GIVEN("a 128 × 8 image, scaled luminance 0.05 left of x = 64 and 20 right of it") {
        const int w = 128, h = 8;
        std::vector<double> L(w * h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) L[y * w + x] = x < 64 ? 0.05 : 20.0;
        rb::LocalOperatorSettings s;
        std::vector<int> scale;
        rb::localAdaptation(L, w, h, s, &scale);
        THEN("pixels next to the edge keep the smallest scale (one pixel)") {
            CHECK(scale[4 * w + 63] == 0);
            CHECK(scale[4 * w + 64] == 0);
        }
        THEN(
            "pixels far from it, whose largest surround (radius 33) stays on their side, take "
            "the largest") {
            // Source: the surround of scale 7 is the blur at s = 1.6^8 = 42.9, α1 s = 15.2,
            // σ = α1 s / √2 = 10.7 pixels, cut at 3σ: 33 pixels; x = 10 reaches x = 43 < 64.
            CHECK(scale[4 * w + 10] == s.scales - 1);
            CHECK(scale[4 * w + 117] == s.scales - 1);
        }
        THEN("the chosen scale never grows towards the edge") {
            for (int x = 1; x < 64; ++x) CHECK(scale[4 * w + x] <= scale[4 * w + x - 1]);
        }
    }
}
// [ch12-local-edge]

// [ch12-local-detail]
SCENARIO("the local operator keeps detail in a bright region that the global one flattens",
         "[ch12][ex12.2][ex12.3]") {
    GIVEN(
        "a film that is dim (0.02) on the left and bright (200) on the right, with stripes "
        "of ±20% in both halves") {
        const int w = 128, h = 16;
        std::vector<double> values(w * h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                values[y * w + x] = (x < 64 ? 0.02 : 200.0) * ((x / 2) % 2 ? 1.2 : 0.8);
        const rb::Image film = greyImage(w, h, values);
        rb::Image global = film, local = film;
        rb::toneMap(global, plain(rb::ToneOperator::Global));
        rb::toneMap(local, plain(rb::ToneOperator::Local));
        /// The display contrast of a stripe pair around x in the middle row.
        const auto contrast = [&](const rb::Image& image, int x) {
            return std::abs(image.get(x + 2, h / 2).g - image.get(x, h / 2).g);
        };
        THEN("in the bright half the local operator shows the stripes at least twice as strong") {
            CHECK(contrast(local, 96) > 2.0 * contrast(global, 96));
            CHECK(contrast(global, 96) > 0.0);
        }
        THEN("and it shows the dim half's stripes at least as well") {
            CHECK(contrast(local, 24) >= contrast(global, 24));
        }
    }
}
// [ch12-local-detail]

// ---- Radiance HDR output --------------------------------------------------------------------

// [ch12-hdr]
SCENARIO("the .hdr file holds the film's radiance to RGBE precision", "[ch12]") {
    GIVEN("a film from 0.001 to 1000, with a negative, a NaN and an infinite value") {
        rb::Image film(4, 2);
        film.set(0, 0, Colour(0.001, 0.002, 0.003));
        film.set(1, 0, Colour(0.5, 0.25, 0.125));
        film.set(2, 0, Colour(3.0, 7.0, 1.0));
        film.set(3, 0, Colour(1000.0, 10.0, 100.0));
        film.set(0, 1, Colour(-1.0, 0.5, 0.5));
        film.set(1, 1, Colour(std::nan(""), 0.5, 0.5));
        film.set(2, 1, Colour(std::numeric_limits<double>::infinity(), 0.5, 0.5));
        film.set(3, 1, Colour(0.0));
        rbtest::TempDir dir;
        const std::string path = (dir.path() / "film.hdr").string();
        rb::writeHdr(film, path);
        WHEN("it is read back with stb_image") {
            int w = 0, h = 0, channels = 0;
            float* back = stbi_loadf(path.c_str(), &w, &h, &channels, 3);
            REQUIRE(back != nullptr);
            THEN("each channel is within 1/128 of its pixel's largest channel") {
                // Source: RGBE keeps an 8-bit mantissa per channel under the largest channel's
                // exponent, so the error is below 2^-8 · 2^e ≤ 2^-7 · max (Ward, Graphics Gems II).
                CHECK(w == 4);
                CHECK(h == 2);
                for (int x = 0; x < 4; ++x) {
                    const Colour c = film.get(x, 0);
                    const double largest = std::max({c.r, c.g, c.b});
                    for (int k = 0; k < 3; ++k)
                        CHECK(std::abs(back[3 * x + k] - c[k]) <= largest / 128.0);
                }
            }
            THEN("a negative or non-finite channel is stored as 0, its neighbours as they are") {
                for (int x = 0; x < 3; ++x) {
                    CHECK(back[3 * (4 + x)] == 0.0f);
                    CHECK(back[3 * (4 + x) + 1] == Approx(0.5).epsilon(1.0 / 128.0));
                }
                CHECK(back[3 * 7] == 0.0f);
            }
            stbi_image_free(back);
        }
        THEN(
            "writing into a folder that does not exist throws, naming the path, and leaves "
            "nothing") {
            const std::string bad = (dir.path() / "missing" / "film.hdr").string();
            CHECK_THROWS_WITH(rb::writeHdr(film, bad), Contains(bad) && Contains("Radiance HDR"));
            CHECK_FALSE(std::filesystem::exists(dir.path() / "missing"));
            CHECK(std::distance(std::filesystem::directory_iterator(dir.path()),
                                std::filesystem::directory_iterator()) == 1);
        }
    }
}
// [ch12-hdr]

// ---- Stability ------------------------------------------------------------------------------

// [ch12-stability]
SCENARIO("a black film tone maps to black, with no NaN", "[ch12][stability][ex12.4]") {
    for (const auto op :
         {rb::ToneOperator::None, rb::ToneOperator::Global, rb::ToneOperator::Local}) {
        GIVEN(std::string("a 16 × 12 black film and the ") +
              rb::kToneOperatorNames[static_cast<int>(op)] + " operator, with sRGB") {
            rb::Image film(16, 12);
            rb::ToneMapSettings s = plain(op);
            s.srgb = true;
            rb::toneMap(film, s);
            THEN("every channel is exactly 0") {
                CHECK(std::all_of(film.data().begin(), film.data().end(),
                                  [](float c) { return c == 0.0f; }));
            }
        }
    }
}

SCENARIO("one bright pixel in a black film does not break the key",
         "[ch12][stability][ex12.1][ex12.3]") {
    for (const double bright : {1.0, 1e6, static_cast<double>(FLT_MAX)}) {
        for (const auto op : {rb::ToneOperator::Global, rb::ToneOperator::Local}) {
            GIVEN("a 16 × 12 black film with one pixel of " + std::to_string(bright) + ", " +
                  rb::kToneOperatorNames[static_cast<int>(op)]) {
                rb::Image film(16, 12);
                film.set(5, 7, Colour(bright));
                rb::toneMap(film, plain(op));
                THEN("the image is displayable, the pixel is bright and the rest black") {
                    CHECK(displayable(film));
                    CHECK(film.get(5, 7).g > 0.5f);
                    CHECK(film.get(0, 0).g == 0.0f);
                }
                if (op == rb::ToneOperator::Global)
                    THEN("with L_white the image's largest, it is exactly white") {
                        CHECK(film.get(5, 7).g == Approx(1.0).epsilon(1e-6));
                    }
            }
        }
    }
}

SCENARIO("NaN, infinite and negative pixels in the film come out black, the rest unharmed",
         "[ch12][stability][ex12.3]") {
    for (const auto op :
         {rb::ToneOperator::None, rb::ToneOperator::Global, rb::ToneOperator::Local}) {
        GIVEN(std::string("a grey film with three broken pixels, ") +
              rb::kToneOperatorNames[static_cast<int>(op)]) {
            rb::Image film = greyImage(8, 8, std::vector<double>(64, 0.4));
            rb::Image clean = film;
            film.set(1, 1, Colour(std::nan("")));
            film.set(2, 2, Colour(std::numeric_limits<double>::infinity()));
            film.set(3, 3, Colour(-5.0));
            // The clean film with the broken pixels black: what the output must equal.
            for (int k = 1; k <= 3; ++k) clean.set(k, k, Colour(0.0));
            rb::toneMap(film, plain(op));
            rb::toneMap(clean, plain(op));
            THEN("the image is displayable and equals the film with those pixels black") {
                CHECK(displayable(film));
                CHECK(rbtest::bitIdentical(film, clean));
            }
        }
    }
}

SCENARIO("a one-pixel film and extreme keys stay displayable", "[ch12][stability][ex12.3]") {
    for (const double key : {1e-6, 0.18, 100.0}) {
        for (const auto op : {rb::ToneOperator::Global, rb::ToneOperator::Local}) {
            GIVEN("key " + std::to_string(key) + ", " +
                  rb::kToneOperatorNames[static_cast<int>(op)]) {
                rb::Image one = greyImage(1, 1, {2.5});
                rb::Image ramp(9, 7);
                for (int y = 0; y < 7; ++y)
                    for (int x = 0; x < 9; ++x) ramp.set(x, y, Colour(std::pow(10.0, x - 4.0)));
                rb::ToneMapSettings s = plain(op, -1.0);
                s.key = key;
                rb::toneMap(one, s);
                rb::toneMap(ramp, s);
                THEN("no channel is NaN or outside [0, 1], and the ramp still rises") {
                    CHECK(displayable(one));
                    CHECK(displayable(ramp));
                    for (int x = 1; x < 9; ++x) CHECK(ramp.get(x, 3).g >= ramp.get(x - 1, 3).g);
                }
            }
        }
    }
}
// [ch12-stability]

// ---- Settings and the switch ----------------------------------------------------------------

// [ch12-settings]
SCENARIO("the tone map is asked for by the scene or the command line, and only then runs",
         "[ch12]") {
    GIVEN("a scene that asks for nothing") {
        THEN("no post-process is installed: the film is written as the course writes it") {
            CHECK(world(kBall)->pipeline.postProcess == nullptr);
        }
        THEN("--tone-map=local installs the local operator, with sRGB on by default") {
            const auto w = world(kBall, {{"tone-map", "local"}});
            REQUIRE(installed(*w));
            CHECK(installed(*w)->settings().op == rb::ToneOperator::Local);
            CHECK(installed(*w)->settings().srgb);
        }
        THEN("--exposure=1 alone installs exposure and clipping, without sRGB") {
            const auto w = world(kBall, {{"exposure", "1"}});
            REQUIRE(installed(*w));
            CHECK(installed(*w)->settings().op == rb::ToneOperator::None);
            CHECK(installed(*w)->settings().exposure == 1.0);
            CHECK_FALSE(installed(*w)->settings().srgb);
        }
        THEN("bad values are refused, naming the option") {
            CHECK_THROWS_WITH(world(kBall, {{"tone-map", "filmic"}}), Contains("--tone-map"));
            CHECK_THROWS_WITH(world(kBall, {{"tone-key", "0"}}), Contains("--tone-key"));
            CHECK_THROWS_WITH(world(kBall, {{"tone-white", "-2"}}), Contains("--tone-white"));
            CHECK_THROWS_WITH(world(kBall, {{"exposure", "nan"}}), Contains("--exposure"));
            CHECK_THROWS_WITH(world(kBall, {{"srgb", "yes"}}), Contains("--srgb"));
        }
    }
    GIVEN("a scene with gr.tone_map{operator = 'global', key = 0.09, white = 4, srgb = false}") {
        const std::string lua =
            "gr.tone_map{operator = 'global', key = 0.09, white = 4, srgb = false}\n" + kBall;
        THEN("it is read, and the command line wins over it") {
            const auto w = world(lua);
            REQUIRE(installed(*w));
            CHECK(installed(*w)->settings().op == rb::ToneOperator::Global);
            CHECK(installed(*w)->settings().key == 0.09);
            CHECK(installed(*w)->settings().white == 4.0);
            CHECK_FALSE(installed(*w)->settings().srgb);
            CHECK(installed(*world(lua, {{"tone-map", "none"}})) == nullptr);
            CHECK(installed(*world(lua, {{"tone-white", "none"}}))->settings().white < 0.0);
        }
        THEN("with chapter 12 switched off it loads and installs nothing") {
            CHECK(world(lua, {}, "all,-tone_map")->pipeline.postProcess == nullptr);
        }
    }
    GIVEN("bad gr.tone_map calls") {
        THEN("each fails naming the field") {
            const auto all = rbtest::chapters(12);
            CHECK_THAT(rbtest::loadError("gr.tone_map{operator = 'aces'}\n" + kBall, all),
                       Contains("field 'operator'"));
            CHECK_THAT(
                rbtest::loadError("gr.tone_map{operator = 'global', kee = 1}\n" + kBall, all),
                Contains("unknown field 'kee'"));
            CHECK_THAT(rbtest::loadError("gr.tone_map{key = -1}\n" + kBall, all),
                       Contains("field 'key'"));
            CHECK_THAT(rbtest::loadError("gr.tone_map{white = 0}\n" + kBall, all),
                       Contains("field 'white'"));
            CHECK_THAT(rbtest::loadError("gr.tone_map{srgb = 1}\n" + kBall, all),
                       Contains("field 'srgb'"));
            CHECK_THAT(rbtest::loadError("gr.tone_map{exposure = 0/0}\n" + kBall, all),
                       Contains("field 'exposure'"));
            CHECK_THAT(rbtest::loadError("gr.tone_map('global')\n" + kBall, all),
                       Contains("expects one table"));
        }
    }
    GIVEN("a chapter-8 build") {
        THEN("gr.tone_map and the tone options fail naming chapter 12") {
            CHECK_THAT(rbtest::loadError("gr.tone_map{operator = 'global'}\n" + kBall,
                                         rbtest::chapters(8)),
                       Contains("chapter 12 (tone_map)"));
            CHECK_THAT(rbtest::loadError("gr.option('exposure', 1)\n" + kBall, rbtest::chapters(8)),
                       Contains("needs chapter 12"));
        }
    }
}
// [ch12-settings]

// [ch12-costs-nothing]
SCENARIO("a scene that asks for no tone map is written exactly as in a chapter-8 build", "[ch12][ex12.4]") {
    GIVEN("the ball scene in a chapter-8 build and in a chapter-12 build with everything on") {
        const auto eight = rbtest::worldFromLua(kBall, rbtest::chapters(8));
        const auto twelve = world(kBall);
        THEN("no post-process is installed and the films and the 8-bit images are identical") {
            CHECK(twelve->pipeline.postProcess == nullptr);
            const rb::Image a = rbtest::renderSmall(*eight, 24, 18);
            const rb::Image b = rbtest::renderSmall(*twelve, 24, 18);
            CHECK(rbtest::bitIdentical(a, b));
            CHECK(rb::toBytes(a) == rb::toBytes(b));
        }
    }
    GIVEN("the same scene with the tone map asked for") {
        const auto twelve = world("gr.tone_map{operator = 'global'}\n" + kBall);
        THEN("the post-process changes the image (so the test above could fail)") {
            REQUIRE(twelve->pipeline.postProcess);
            rb::Image film = rbtest::renderSmall(*twelve, 24, 18);
            const rb::Image before = film;
            twelve->pipeline.postProcess->apply(film);
            CHECK_FALSE(rbtest::bitIdentical(film, before));
        }
    }
}
// [ch12-costs-nothing]
