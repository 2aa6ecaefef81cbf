#include "app/block_stats.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rb::golden {

namespace {

/// The pixel rectangle of group (gx, gy) of g × g blocks: [x0, x1) × [y0, y1).
struct Rect {
    int x0, y0, x1, y1;
};

Rect rect(const BlockStats& s, int g, int gx, int gy) {
    const int side = g * s.block;
    return {gx * side, gy * side, std::min(s.w, (gx + 1) * side), std::min(s.h, (gy + 1) * side)};
}

/// The mean of channel c of image over the rectangle.
double mean_over(const Image& image, const Rect& r, int c) {
    double sum = 0.0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) sum += image.at(x, y, c);
    return sum / ((r.x1 - r.x0) * (r.y1 - r.y0));
}

}  // namespace

constexpr int BlockStats::kGroups[4];

BlockStats block_stats(const std::vector<Image>& renders, int block) {
    if (renders.size() < 4) throw std::runtime_error("block statistics need at least 4 renders");
    if (block < 1) throw std::runtime_error("block statistics: the block side must be positive");
    BlockStats s;
    s.w = renders[0].w;
    s.h = renders[0].h;
    s.block = block;
    s.renders = static_cast<int>(renders.size());
    for (const Image& r : renders)
        if (r.w != s.w || r.h != s.h)
            throw std::runtime_error("block statistics: the renders differ in size");
    const double k = s.renders;
    for (int i = 0; i < 4; ++i) {
        const int g = BlockStats::kGroups[i];
        for (int gy = 0; gy < s.groupsY(g); ++gy)
            for (int gx = 0; gx < s.groupsX(g); ++gx)
                for (int c = 0; c < 3; ++c) {
                    // The group's mean in each render; their mean and sample deviation.
                    std::vector<double> m;
                    for (const Image& image : renders)
                        m.push_back(mean_over(image, rect(s, g, gx, gy), c));
                    double mean = 0.0, m2 = 0.0;
                    for (const double v : m) mean += v / k;
                    for (const double v : m) m2 += (v - mean) * (v - mean);
                    s.mean[i].push_back(mean);
                    s.sigma[i].push_back(std::sqrt(m2 / (k - 1.0)));
                }
    }
    return s;
}

void save_block_stats(const std::filesystem::path& path, const BlockStats& s) {
    std::ofstream out(path);
    out.precision(9);
    out << "# raybook block statistics (src/app/block_stats.h): for groups of G x G blocks of "
        << s.block << " x " << s.block << " pixels, row by row, r g b: the mean of the group's "
        << "mean over " << s.renders << " reference renders (seeds 1 to " << s.renders
        << ") and the standard deviation of one render's group mean\n";
    out << "size " << s.w << "x" << s.h << "\nblock " << s.block << "\nrenders " << s.renders
        << "\n";
    for (int i = 0; i < 4; ++i) {
        out << "groups " << BlockStats::kGroups[i] << "\n";
        for (std::size_t j = 0; j < s.mean[i].size(); j += 3) {
            for (std::size_t c = 0; c < 3; ++c)
                out << (c ? " " : "") << s.mean[i][j + c] << " " << s.sigma[i][j + c];
            out << "\n";
        }
    }
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

BlockStats load_block_stats(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return parse_block_stats(in, path.string());
}

BlockStats parse_block_stats(std::istream& in, const std::string& source) {
    BlockStats s;
    std::string line, key;
    char x = 0;
    int section = -1;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        if (!std::isdigit(static_cast<unsigned char>(line[0])) && line[0] != '-') {
            fields >> key;
            if (key == "size") fields >> s.w >> x >> s.h;
            if (key == "block") fields >> s.block;
            if (key == "renders") fields >> s.renders;
            if (key == "groups") ++section;
            continue;
        }
        double mean = 0.0, sigma = 0.0;
        while (section >= 0 && section < 4 && fields >> mean >> sigma) {
            s.mean[section].push_back(mean);
            s.sigma[section].push_back(sigma);
        }
    }
    // Sides within the golden renders' limit also keep the block and group counts from
    // overflowing.
    if (s.w > kMaxSide || s.h > kMaxSide || s.block > kMaxSide)
        throw std::runtime_error(source + ": size " + std::to_string(s.w) + "x" +
                                 std::to_string(s.h) + " or block " + std::to_string(s.block) +
                                 " beyond " + std::to_string(kMaxSide) + " pixels");
    bool ok = s.w > 0 && s.h > 0 && s.block > 0 && s.renders >= 2 && section == 3;
    for (int i = 0; ok && i < 4; ++i) {
        const int g = BlockStats::kGroups[i];
        ok = s.mean[i].size() == 3 * static_cast<std::size_t>(s.groupsX(g) * s.groupsY(g));
    }
    if (!ok) throw std::runtime_error(source + ": not a block statistics file");
    return s;
}

double normal_quantile(double p) {
    // Φ(z) = erfc(−z/√2)/2 is increasing: bisect.
    double lo = -40.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

int binomial_upper(int n, double p, double alpha) {
    // P(X > c) = 1 − Σ_{i ≤ c} C(n, i) pⁱ (1 − p)^(n−i), the terms from logarithms.
    double cumulative = 0.0;
    for (int c = 0; c <= n; ++c) {
        const double logTerm = std::lgamma(n + 1.0) - std::lgamma(c + 1.0) -
                               std::lgamma(n - c + 1.0) + c * std::log(p) +
                               (n - c) * std::log1p(-p);
        cumulative += std::exp(logTerm);
        if (1.0 - cumulative <= alpha) return c;
    }
    return n;
}

StatisticalComparison compare_statistically(const BlockStats& s, const Image& actual,
                                            const StatisticalLimits& limits) {
    StatisticalComparison result;
    if (actual.w != s.w || actual.h != s.h) {
        result.reason = "size " + std::to_string(actual.w) + "x" + std::to_string(actual.h) +
                        ", the reference statistics are for " + std::to_string(s.w) + "x" +
                        std::to_string(s.h);
        return result;
    }
    // Source: under H0 the render's group mean m has mean μ and variance v ≤ λσ², and μ (an
    // average of K renders) has variance σ²/K, so z = (m − μ)/√(λσ² + σ²/K) has variance ≤ 1;
    // means of many pixels are near normal (the central limit theorem). σ is itself measured
    // from K renders; the allowance λ = 2 also covers its error (about 1/√(2(K − 1)), 13% for
    // K = 32). A bias confined to a region shows best in groups the size of the region, so
    // groups of 1, 2, 4 and 8 blocks a side are each tested: a channel's |z| beyond the block
    // threshold makes a group "off", and more off groups than Binomial(groups, block_alpha)
    // gives at alpha fail.
    const double zBlock = normal_quantile(1.0 - limits.block_alpha / 6.0);
    const double k = s.renders;
    result.passed = true;
    for (int i = 0; i < 4; ++i) {
        const int g = BlockStats::kGroups[i];
        const int groups = s.groupsX(g) * s.groupsY(g);
        int off = 0;
        for (int gy = 0; gy < s.groupsY(g); ++gy)
            for (int gx = 0; gx < s.groupsX(g); ++gx) {
                const std::size_t at = 3 * static_cast<std::size_t>(gy * s.groupsX(g) + gx);
                double largest = 0.0, greyShift = 0.0, greySpread = 0.0;
                for (int c = 0; c < 3; ++c) {
                    const double sigma = s.sigma[i][at + c];
                    const double spread =
                        std::sqrt(limits.variance_ratio * sigma * sigma + sigma * sigma / k +
                                  limits.sigma_floor * limits.sigma_floor);
                    const double shift =
                        mean_over(actual, rect(s, g, gx, gy), c) - s.mean[i][at + c];
                    // A NaN pixel makes the group infinitely far off.
                    const double z = std::abs(shift) / spread;
                    largest = std::max(largest, std::isnan(z) ? HUGE_VAL : z);
                    greyShift += shift / 3.0;
                    greySpread += spread / 3.0;  // ≥ the grey mean's, however correlated
                }
                if (largest > zBlock) ++off;
                if (g == 1) {
                    const double zGrey = greyShift / greySpread;
                    result.chi2 += std::isnan(zGrey) ? HUGE_VAL : zGrey * zGrey;
                    result.mean_shift += zGrey / groups;
                }
            }
        const int allowed = binomial_upper(groups, limits.block_alpha, limits.alpha);
        // Report the size that is furthest past its allowance (the blocks, when none is).
        if (g == 1 || off - allowed > result.off_blocks - result.allowed_off) {
            result.group = g;
            result.blocks = groups;
            result.off_blocks = off;
            result.allowed_off = allowed;
        }
        if (off > allowed) result.passed = false;
    }
    // Source: Wilson and Hilferty (1931): (χ²_n / n)^(1/3) is near normal with mean
    // 1 − 2/(9n) and variance 2/(9n). (Neighbouring blocks of a photon map are slightly
    // correlated; the allowance λ keeps Σ z² well below n even so.)
    const double n = s.blocks(), zAlpha = normal_quantile(1.0 - limits.alpha);
    result.chi2_limit =
        n * std::pow(1.0 - 2.0 / (9.0 * n) + zAlpha * std::sqrt(2.0 / (9.0 * n)), 3);
    if (!(result.chi2 <= result.chi2_limit)) result.passed = false;
    return result;
}

std::string describe(const StatisticalComparison& c) {
    if (!c.reason.empty()) return c.reason;
    std::ostringstream text;
    text.precision(3);
    const std::string unit = c.group == 1 ? "blocks"
                                          : "groups of " + std::to_string(c.group) + " x " +
                                                std::to_string(c.group) + " blocks";
    text << (c.passed ? "the same estimate as the reference" : "a different estimate") << " ("
         << c.off_blocks << " of " << c.blocks << " " << unit << " off, allowed " << c.allowed_off
         << "; chi-square of the block means " << c.chi2
         << (c.chi2 <= c.chi2_limit ? " <= " : " > ") << c.chi2_limit << "; mean shift "
         << c.mean_shift << " sigma)";
    return text.str();
}

}  // namespace rb::golden
