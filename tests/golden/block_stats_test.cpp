/// \file
/// Tests of the statistical golden check (block_stats.h) on synthetic Monte Carlo renders: a
/// smooth picture plus independent Gaussian noise per pixel, stored as 8-bit PNG values. The
/// check must accept a render that drew other random numbers, at its stated false-alarm rate,
/// and one that is somewhat noisier, and must reject a small bias, global or local.
#include "app/block_stats.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <sstream>

using rb::golden::BlockStats;
using rb::golden::Image;

namespace {

constexpr int kW = 192, kH = 144;

/// The picture every render estimates: a ramp across, 0.3 to 0.7.
double truth(int x, int, int c) {
    return 0.3 + 0.4 * x / kW + 0.05 * c;
}

/// A pixel's noise: larger towards the bottom (from 0.05 to 0.1), as Monte Carlo noise varies.
double noise(int y) {
    return 0.05 * (1.0 + static_cast<double>(y) / kH);
}

/// One render from random stream `seed`: truth + bias(x, y) + noise·√variance_ratio · N(0, 1),
/// rounded to 8 bits as a PNG stores it.
template <class Bias>
Image render(std::uint64_t seed, double varianceRatio, Bias bias) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    Image image = Image::filled(kW, kH, 0, 0, 0);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v =
                    truth(x, y, c) + bias(x, y) + noise(y) * std::sqrt(varianceRatio) * normal(rng);
                image.at(x, y, c) =
                    static_cast<float>(std::round(std::clamp(v, 0.0, 1.0) * 255) / 255);
            }
    return image;
}

Image unbiased(std::uint64_t seed, double varianceRatio = 1.0) {
    return render(seed, varianceRatio, [](int, int) { return 0.0; });
}

/// The reference statistics: 32 renders, seeds 1 to 32, as run_golden.sh makes them.
const BlockStats& reference() {
    static const BlockStats stats = [] {
        std::vector<Image> renders;
        for (std::uint64_t seed = 1; seed <= 32; ++seed) renders.push_back(unbiased(seed));
        return rb::golden::block_stats(renders);
    }();
    return stats;
}

/// How many of `count` renders (seeds from 1000) fail the check.
template <class Make>
int failures(int count, Make make) {
    int failed = 0;
    for (int i = 0; i < count; ++i)
        failed += !rb::golden::compare_statistically(reference(), make(1000 + i)).passed;
    return failed;
}

}  // namespace

SCENARIO("the statistical golden check accepts a render that drew other random numbers",
         "[golden][stats]") {
    GIVEN("reference statistics from 32 renders of a noisy ramp") {
        WHEN("200 more renders of the same estimator, from other seeds, are checked") {
            const int failed = failures(200, [](std::uint64_t s) { return unbiased(s); });
            THEN("no more fail than the stated false-alarm rate allows") {
                // Source: five tests at alpha = 0.001 each, so P(fail) <= 0.005 per render; at
                // most binomial_upper(200, 0.005, 0.001) = 5 of 200 (the count's 99.9% bound).
                INFO(failed << " of 200 failed");
                CHECK(failed <= rb::golden::binomial_upper(200, 0.005, 0.001));
            }
        }
        WHEN("50 renders 1.5 times as noisy (another, poorer stratification) are checked") {
            const int failed = failures(50, [](std::uint64_t s) { return unbiased(s, 1.5); });
            THEN("they pass as often: the check allows twice the reference's variance") {
                INFO(failed << " of 50 failed");
                CHECK(failed <= rb::golden::binomial_upper(50, 0.005, 0.001));
            }
        }
    }
}

SCENARIO("the statistical golden check rejects biased renders", "[golden][stats]") {
    GIVEN("the same reference statistics") {
        WHEN("every pixel is brighter by a fifth of its noise") {
            const int failed = failures(20, [](std::uint64_t s) {
                return render(s, 1.0, [](int, int y) { return 0.2 * noise(y); });
            });
            THEN("every render fails (the sum of z-squared over the blocks)") {
                // Source: a block mean of 64 pixels moves by 0.2·8 = 1.6 of its σ, 1.6/√2.03 =
                // 1.1 in z: Σ z² over 432 blocks grows by about 1.2·432 = 520, far past the
                // limit's margin above its mean (about 3.1·√(2·432) = 91).
                CHECK(failed == 20);
            }
        }
        WHEN("a 48 x 48 region is brighter by a quarter of its noise") {
            const int failed = failures(20, [](std::uint64_t s) {
                return render(s, 1.0, [](int x, int y) {
                    return x >= 64 && x < 112 && y >= 48 && y < 96 ? 0.25 * noise(y) : 0.0;
                });
            });
            THEN("at least 17 of 20 renders fail (the groups of 4 x 4 blocks see it)") {
                // Source: the one 32 x 32 group wholly inside the region moves by 0.25·32 = 8
                // of its σ, 8/√2.03 = 5.6 in z, beyond the group threshold
                // Φ⁻¹(1 − 0.001/6) = 3.6 with probability Φ(2.0) = 0.977 (more with the groups
                // of 2 x 2 blocks); P(at most 16 of 20 | 0.977) = 0.0012.
                INFO(failed << " of 20 failed");
                CHECK(failed >= 17);
            }
        }
        WHEN("the renders are four times as noisy") {
            const int failed = failures(20, [](std::uint64_t s) { return unbiased(s, 4.0); });
            THEN("they fail: that is not the reference's estimator") {
                CHECK(failed >= 18);
            }
        }
    }
}

SCENARIO("the statistics file keeps what was measured", "[golden][stats]") {
    GIVEN("the reference statistics written to a file") {
        const auto path = std::filesystem::temp_directory_path() / "rb-block-stats-test.stats";
        rb::golden::save_block_stats(path, reference());
        WHEN("it is read back") {
            const BlockStats back = rb::golden::load_block_stats(path);
            THEN(
                "the size, the renders and every group's mean and sigma are the same to 9 digits") {
                CHECK(back.w == kW);
                CHECK(back.h == kH);
                CHECK(back.renders == 32);
                for (int g = 0; g < 4; ++g) {
                    REQUIRE(back.mean[g].size() == reference().mean[g].size());
                    for (std::size_t i = 0; i < back.mean[g].size(); ++i) {
                        CHECK(back.mean[g][i] == Approx(reference().mean[g][i]).epsilon(1e-8));
                        CHECK(back.sigma[g][i] == Approx(reference().sigma[g][i]).epsilon(1e-8));
                    }
                }
            }
        }
        std::filesystem::remove(path);
    }
}

SCENARIO("a statistics file must state a size a golden render can have", "[golden][stats]") {
    GIVEN("a file whose width is 2^31 - 1 (found by fuzz_stats: the block count overflowed)") {
        std::istringstream in(
            "size 2147483647x12\nblock 8\nrenders 4\ngroups 1\ngroups 2\n"
            "groups 4\ngroups 8\n");
        THEN("it is refused, naming the file, the size and the limit") {
            REQUIRE_THROWS_WITH(
                rb::golden::parse_block_stats(in, "golden/x.stats"),
                Catch::Matchers::Contains("golden/x.stats: size 2147483647x12 or block 8") &&
                    Catch::Matchers::Contains("beyond 16384 pixels"));
        }
    }
}

SCENARIO("the limits come from their distributions", "[golden][stats]") {
    THEN("the normal quantile of 0.975 is 1.95996 and of 0.001 is -3.09023") {
        // Source: standard normal tables (Abramowitz and Stegun, table 26.5).
        CHECK(rb::golden::normal_quantile(0.975) == Approx(1.959964).epsilon(1e-6));
        CHECK(rb::golden::normal_quantile(0.001) == Approx(-3.090232).epsilon(1e-6));
    }
    THEN("Binomial(432, 0.001) exceeds 3 with probability above 0.001, and 4 below it") {
        // Source: with λ = np = 0.432 (Poisson limit, within 0.1% of the binomial here),
        // P(X > 3) = 1 − e^(−λ)(1 + λ + λ²/2 + λ³/6) = 0.00107 and
        // P(X > 4) = 1 − e^(−λ)(1 + λ + λ²/2 + λ³/6 + λ⁴/24) = 0.00013.
        CHECK(rb::golden::binomial_upper(432, 0.001, 0.001) == 4);
    }
}
