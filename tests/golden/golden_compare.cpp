/// \file
/// Tests of the golden-image metric that every chapter's reference render is judged by.
//
// The golden runner promises: a chapter scene rendered at a fixed size and seed either matches
// its reference in golden/ or fails with one line that says by how much. "Matches" means two
// things recorded next to the image: the RMSE over all channels of all pixels stays within
// `rmse`, and no more than `max_fraction` of the pixels have a channel off by more than
// `pixel_tol`. The first catches a global shift (a wrong constant, a missing light); the second
// catches a small local break (a leaking edge, a firefly) that RMSE would average away. The tests
// below build images in memory whose metrics are known in closed form and check the comparison
// against them, then check that the thresholds file is read strictly.

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>

#include "app/compare.h"
#include "app/image_compare.h"

using namespace rb::golden;
using Catch::Matchers::Contains;

namespace {

/// Thresholds with the project defaults (rmse 0.004, pixel_tol 0.02, max_fraction 0.002).
Thresholds default_thresholds() {
    return Thresholds{};
}

/// Parses thresholds from a string, as if read from a file called "golden/test.txt".
Thresholds parse(const std::string& text) {
    std::istringstream in(text);
    return parse_thresholds(in, "golden/test.txt");
}

}  // namespace

SCENARIO("a render identical to its golden image passes with zero error", "[golden]") {
    GIVEN("two identical 192x144 images with a gradient") {
        Image expected = Image::filled(192, 144, 0, 0, 0);
        for (int y = 0; y < expected.h; ++y)
            for (int x = 0; x < expected.w; ++x)
                for (int c = 0; c < 3; ++c) expected.at(x, y, c) = float((x + y + c) % 256) / 255;
        const Image actual = expected;
        WHEN("they are compared") {
            const Comparison result = compare(expected, actual, default_thresholds());
            THEN("RMSE, outliers and the largest difference are all zero, PSNR is infinite") {
                REQUIRE(result.rmse == 0.0);
                REQUIRE(result.outlier_fraction == 0.0);
                REQUIRE(result.max_diff == 0.0);
                REQUIRE(std::isinf(result.psnr));
                REQUIRE(result.passed);
            }
        }
    }
}

SCENARIO("a uniform offset d gives an RMSE of exactly d", "[golden]") {
    GIVEN("a grey image and the same image brightened by d = 1/64 in every channel") {
        // d = 1/64 and 0.25 + d are exact in float, so the closed form holds to rounding of sqrt
        const double d = 1.0 / 64.0;
        const Image expected = Image::filled(40, 30, 0.25f, 0.25f, 0.25f);
        const Image actual =
            Image::filled(40, 30, 0.25f + float(d), 0.25f + float(d), 0.25f + float(d));
        WHEN("they are compared with pixel_tol 0.02 (above d)") {
            const Comparison result = compare(expected, actual, default_thresholds());
            THEN("RMSE = sqrt(sum of d^2 over 3N channels / 3N) = d, and PSNR = -20 log10 d") {
                // Source: the definition of RMSE with every term equal to d^2.
                REQUIRE(result.rmse == Approx(d).epsilon(1e-12));
                REQUIRE(result.psnr == Approx(-20.0 * std::log10(d)).epsilon(1e-12));
                REQUIRE(result.max_diff == Approx(d).epsilon(1e-12));
            }
            THEN("no pixel is an outlier, but the RMSE threshold 0.004 fails the render") {
                REQUIRE(result.outlier_fraction == 0.0);
                REQUIRE_FALSE(result.passed);
                REQUIRE(describe(result, default_thresholds()) ==
                        "RMSE 0.0156 > 0.004; 0% of pixels beyond 0.02 (allowed 0.2%)");
            }
        }
        WHEN("they are compared with pixel_tol 0.01 (below d)") {
            Thresholds thresholds = default_thresholds();
            thresholds.pixel_tol = 0.01;
            thresholds.rmse = 0.02;
            thresholds.max_fraction = 1.0;
            const Comparison result = compare(expected, actual, thresholds);
            THEN("every pixel is an outlier") {
                REQUIRE(result.outlier_fraction == 1.0);
                REQUIRE(result.outlier_count == 40 * 30);
                REQUIRE(result.passed);
            }
        }
    }
}

SCENARIO("one bright pixel among N is an outlier fraction of 1/N", "[golden]") {
    GIVEN("a black 16x16 image and a copy with one white pixel") {
        const Image expected = Image::filled(16, 16, 0, 0, 0);
        Image actual = expected;
        for (int c = 0; c < 3; ++c) actual.at(5, 7, c) = 1.0f;
        WHEN("they are compared") {
            const Comparison result = compare(expected, actual, default_thresholds());
            THEN("the outlier fraction is 1/256 and RMSE is sqrt(3 / (3 * 256)) = 1/16") {
                // Source: three squared differences of 1 among 3 * 256 channel terms.
                REQUIRE(result.outlier_count == 1);
                REQUIRE(result.outlier_fraction == Approx(1.0 / 256.0).epsilon(1e-12));
                REQUIRE(result.rmse == Approx(1.0 / 16.0).epsilon(1e-12));
                REQUIRE(result.max_diff == 1.0);
            }
            THEN("it fails, since 1/256 = 0.39% is above the allowed 0.2%") {
                REQUIRE_FALSE(result.passed);
            }
        }
        WHEN("the diff image is made") {
            const Image diff = diff_image(expected, actual, 0.02);
            THEN("the outlier is pure magenta and the rest stays black") {
                REQUIRE(diff.at(5, 7, 0) == 1.0f);
                REQUIRE(diff.at(5, 7, 1) == 0.0f);
                REQUIRE(diff.at(5, 7, 2) == 1.0f);
                REQUIRE(diff.at(0, 0, 0) == 0.0f);
                REQUIRE(diff.at(15, 15, 1) == 0.0f);
            }
        }
    }
}

SCENARIO("a small difference is magnified eight times in the diff image", "[golden]") {
    GIVEN("two images that differ by 0.01 in green only") {
        const Image expected = Image::filled(4, 4, 0.5f, 0.5f, 0.5f);
        const Image actual = Image::filled(4, 4, 0.5f, 0.51f, 0.5f);
        WHEN("the diff image is made with pixel_tol 0.02") {
            const Image diff = diff_image(expected, actual, 0.02);
            THEN("green shows 8 * 0.01 = 0.08 and red and blue show nothing") {
                REQUIRE(diff.at(2, 2, 0) == 0.0f);
                REQUIRE(diff.at(2, 2, 1) == Approx(0.08).epsilon(1e-5));
                REQUIRE(diff.at(2, 2, 2) == 0.0f);
            }
        }
    }
}

SCENARIO("a render of the wrong size fails with a clear reason", "[golden]") {
    GIVEN("a 192x144 golden image and a 200x150 render") {
        const Image expected = Image::filled(192, 144, 0, 0, 0);
        const Image actual = Image::filled(200, 150, 0, 0, 0);
        WHEN("they are compared") {
            const Comparison result = compare(expected, actual, default_thresholds());
            THEN("it fails and the reason names both sizes") {
                REQUIRE_FALSE(result.passed);
                REQUIRE(result.size_mismatch);
                REQUIRE(describe(result, default_thresholds()) ==
                        "image size 200x150 differs from golden 192x144");
            }
        }
        WHEN("the diff image is made") {
            const Image diff = diff_image(expected, actual, 0.02);
            THEN("it covers both images and marks the uncovered pixels magenta") {
                REQUIRE(diff.w == 200);
                REQUIRE(diff.h == 150);
                REQUIRE(diff.at(0, 0, 0) == 0.0f);
                REQUIRE(diff.at(199, 149, 0) == 1.0f);
                REQUIRE(diff.at(199, 149, 1) == 0.0f);
            }
        }
    }
}

SCENARIO("the verdict line never prints a failing value equal to its limit", "[golden]") {
    GIVEN("an RMSE just above the threshold 0.004") {
        Comparison result;
        result.rmse = 0.0040004;
        result.outlier_fraction = 0.0001;
        result.passed = false;
        WHEN("it is described") {
            const std::string text = describe(result, default_thresholds());
            THEN("enough digits are shown to see that it exceeds the threshold") {
                REQUIRE(text ==
                        "RMSE 0.0040004 > 0.004; 0.01% of pixels beyond 0.02 (allowed 0.2%)");
            }
        }
    }
}

SCENARIO("a PNG round trip keeps every 8-bit value", "[golden]") {
    GIVEN("an image whose channels are multiples of 1/255") {
        Image image = Image::filled(7, 5, 0, 0, 0);
        for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = float(i * 7 % 256) / 255;
        WHEN("it is saved as PNG and loaded again") {
            const auto path = std::filesystem::temp_directory_path() /
                              ("rb_golden_roundtrip_" + std::to_string(::getpid()) + ".png");
            save_png(path, image);
            const Image loaded = load_png(path);
            std::filesystem::remove(path);
            THEN("size and values are unchanged, so the comparison sees zero error") {
                REQUIRE(loaded.w == 7);
                REQUIRE(loaded.h == 5);
                REQUIRE(compare(image, loaded, Thresholds{}).rmse == 0.0);
            }
        }
    }
    GIVEN("a path that holds no image") {
        THEN("loading throws, naming the file and saying in words what is wrong") {
            REQUIRE_THROWS_WITH(load_png("/nonexistent/golden.png"),
                                Contains("/nonexistent/golden.png: there is no such file"));
        }
    }
    GIVEN("a folder where an image belongs") {
        const std::filesystem::path folder = std::filesystem::temp_directory_path();
        THEN("loading says it is a folder, not a file") {
            REQUIRE_THROWS_WITH(load_png(folder), Contains(": it is a folder, not a file"));
        }
    }
}

SCENARIO("--compare reads PNG files of a size it can hold, and refuses others before decoding",
         "[golden]") {
    // Inputs that fuzz_compare found (tests/fuzz/README.md, findings 10 and 13), reduced, and
    // what the refusal must say.
    struct Case {
        const char* given;
        std::string bytes;
        const char* message;
    };
    const Case cases[] = {
        {"the 33-byte start of a PNG whose header declares 2050 x 65534 pixels (the size of a "
         "41-byte GIF for which stb allocated 1.4 GB)",
         std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x08\x02\0\0\xff\xfe"
                     "\x08\x02\0\0\0\0\0\0\0",
                     33),
         "x.png: its header declares 2050x65534 pixels"},
        {"a PNG whose second chunk declares 273 MB in a file of 44 bytes (stb grew a buffer to "
         "2 GiB for it before reading)",
         std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\0\x04\0\0\0\x03"
                     "\x08\x02\0\0\0\0\0\0\0\x10\x49\x44\x41IDATxyz",
                     44),
         "x.png: a chunk declares 273237057 bytes"},
        {"an image in another format stb reads (the GIF's header), whose readers stb never runs",
         std::string("GIF89a\x02\x08\xfe\xff\0\0\0", 13), "x.png: not a PNG file"},
        {"a PNG of 4 x 3 pixels whose pixel data is not zlib data (stb says only 'bad zlib "
         "header')",
         std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\0\x04\0\0\0\x03"
                     "\x08\x02\0\0\0\0\0\0\0\0\0\0\x04IDATxyz!\0\0\0\0\0\0\0\0IEND\0\0\0\0",
                     61),
         "x.png: its PNG data is damaged or of a kind rt cannot decode (stb_image: "},
    };
    for (const Case& c : cases) {
        GIVEN(c.given) {
            THEN("it is refused, saying why and naming the file") {
                REQUIRE_THROWS_WITH(decode_png(c.bytes, "x.png"), Contains(c.message));
            }
        }
    }
}

SCENARIO("a thresholds file is read strictly", "[golden]") {
    GIVEN("a complete file with comments and rt arguments") {
        const Thresholds t = parse(
            "# chapter 5: glass needs more samples\n"
            "size 128x96\n"
            "seed 7\n"
            "\n"
            "rmse 0.005   # noisy caustics\n"
            "pixel_tol 0.03\n"
            "max_fraction 0.001\n"
            "args --spp 16 --max-depth 8\n");
        THEN("every key is read, and args keeps the rest of its line") {
            REQUIRE(t.width == 128);
            REQUIRE(t.height == 96);
            REQUIRE(t.seed == 7u);
            REQUIRE(t.rmse == 0.005);
            REQUIRE(t.pixel_tol == 0.03);
            REQUIRE(t.max_fraction == 0.001);
            REQUIRE(t.extra_args == "--spp 16 --max-depth 8");
        }
    }
    GIVEN("a file that gives only the size") {
        const Thresholds t = parse("size 256x192\n");
        THEN("the other keys keep the project defaults") {
            REQUIRE(t.width == 256);
            REQUIRE(t.rmse == 0.004);
            REQUIRE(t.pixel_tol == 0.02);
            REQUIRE(t.max_fraction == 0.002);
            REQUIRE(t.seed == 1u);
            REQUIRE(t.extra_args.empty());
        }
    }
    GIVEN("a malformed value on line 3") {
        const std::string text = "size 192x144\nseed 1\nrmse zero\n";
        THEN("parsing throws, naming the file, the line and the key") {
            REQUIRE_THROWS_AS(parse(text), std::runtime_error);
            REQUIRE_THROWS_WITH(parse(text), Contains("golden/test.txt:3:") && Contains("rmse"));
        }
    }
    GIVEN("other mistakes") {
        THEN("a bad size, an unknown key, a repeated key and trailing text are all rejected") {
            REQUIRE_THROWS_WITH(parse("size 192by144\n"), Contains("golden/test.txt:1:"));
            REQUIRE_THROWS_WITH(parse("seed 1\nrmsee 0.1\n"),
                                Contains("golden/test.txt:2:") && Contains("unknown key"));
            REQUIRE_THROWS_WITH(parse("seed 1\nseed 2\n"), Contains("twice"));
            REQUIRE_THROWS_WITH(parse("pixel_tol 0.02 0.03\n"), Contains("pixel_tol"));
            REQUIRE_THROWS_WITH(parse("max_fraction 2\n"), Contains("max_fraction"));
            REQUIRE_THROWS_WITH(parse("seed -1\n"), Contains("seed"));
        }
    }
}

SCENARIO("./rt --compare prints RMSE, PSNR, the largest difference and the pixels over one level",
         "[golden]") {
    GIVEN("a black 10x10 image, and a copy with one white pixel and one channel one level up") {
        const auto dir =
            std::filesystem::temp_directory_path() / ("rb_compare_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        const Image black = Image::filled(10, 10, 0, 0, 0);
        Image other = black;
        for (int c = 0; c < 3; ++c) other.at(3, 4, c) = 1.0f;
        other.at(7, 1, 2) = 1.0f / 255;
        save_png(dir / "a.png", black);
        save_png(dir / "b.png", other);
        const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string();
        // Source: the definitions. Squared differences: 3 channels of 1, one of (1/255)², over
        // 300 channel values; PSNR = 20 log10(1 / RMSE) for values in [0, 1]. Only the white
        // pixel is over one level: 1 of 100.
        const double rmse = std::sqrt((3.0 + 1.0 / (255.0 * 255.0)) / 300.0);
        char expected[160];
        std::snprintf(expected, sizeof expected, "RMSE      %.6g", rmse);
        char psnr[64];
        std::snprintf(psnr, sizeof psnr, "PSNR      %.2f dB", 20.0 * std::log10(1.0 / rmse));
        WHEN("they are compared with the default threshold, 0") {
            std::ostringstream out, err;
            const int code =
                rb::compareCommand({a, b, "--diff", (dir / "d.png").string()}, out, err);
            THEN("it prints the closed-form numbers, writes the difference and exits 1") {
                CHECK_THAT(out.str(), Contains(expected));
                CHECK_THAT(out.str(), Contains(psnr));
                CHECK_THAT(out.str(), Contains("largest   1 (255 of 255 levels)"));
                CHECK_THAT(out.str(), Contains("over one level  1% of pixels (1 of 100)"));
                // Magenta (1, 0, 1) marks the pixel over one level; |difference| x 8 alone
                // would be white there.
                const Image diff = load_png(dir / "d.png");
                CHECK((diff.at(3, 4, 0) == 1.0f && diff.at(3, 4, 1) == 0.0f &&
                       diff.at(3, 4, 2) == 1.0f));
                CHECK(code == 1);
            }
        }
        WHEN("the threshold is above that RMSE, or the image is compared with itself") {
            std::ostringstream out, err;
            THEN("it exits 0") {
                CHECK(rb::compareCommand({a, b, "--threshold", "0.11"}, out, err) == 0);
                CHECK(rb::compareCommand({a, a}, out, err) == 0);
            }
        }
        WHEN("an argument is missing or an image cannot be read") {
            std::ostringstream out, err;
            THEN("it exits 1 with a message naming what is wrong") {
                CHECK(rb::compareCommand({a}, out, err) == 1);
                CHECK(rb::compareCommand({a, (dir / "none.png").string()}, out, err) == 1);
                CHECK(rb::compareCommand({a, b, "--threshold", "-1"}, out, err) == 1);
                CHECK_THAT(err.str(), Contains("expected two images"));
                CHECK_THAT(err.str(), Contains("none.png"));
                CHECK_THAT(err.str(), Contains("--threshold"));
            }
        }
        std::filesystem::remove_all(dir);
    }
}
