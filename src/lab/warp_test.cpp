#include "lab/warp_test.h"

#include <stb_image_write.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/from_chars.h"
#include "core/image.h"

namespace rb {

namespace {

/// The level of one sampler's test on the command line.
constexpr double kAlpha = 0.01;
/// The side of one panel of the figure, in pixels.
constexpr int kPanel = 240;

// ---- Integration --------------------------------------------------------------------------

/// Simpson's rule on a rectangle: the tensor product of the 1-D rule, 9 points.
double simpsonRectangle(const std::function<double(const Vec2&)>& f, double x0, double x1,
                        double y0, double y1) {
    const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
    const double corners = f({x0, y0}) + f({x1, y0}) + f({x0, y1}) + f({x1, y1});
    const double edges = f({xm, y0}) + f({xm, y1}) + f({x0, ym}) + f({x1, ym});
    return (x1 - x0) * (y1 - y0) / 36.0 * (corners + 4.0 * edges + 16.0 * f({xm, ym}));
}

/// Adaptive Simpson cubature: split into four until the four agree with the whole to `tol`
/// (Richardson's correction, as in the 1-D rule), or `depth` runs out (at a jump of f, such
/// as the edge of a disk, the error halves with each level).
double adaptiveSimpson(const std::function<double(const Vec2&)>& f, double x0, double x1, double y0,
                       double y1, double whole, double tol, int depth, int minDepth) {
    const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
    const double a = simpsonRectangle(f, x0, xm, y0, ym), b = simpsonRectangle(f, xm, x1, y0, ym);
    const double c = simpsonRectangle(f, x0, xm, ym, y1), d = simpsonRectangle(f, xm, x1, ym, y1);
    const double parts = a + b + c + d;
    if (depth <= 0 || (minDepth <= 0 && std::abs(parts - whole) <= 15.0 * tol))
        return parts + (parts - whole) / 15.0;
    const double t = 0.25 * tol;
    return adaptiveSimpson(f, x0, xm, y0, ym, a, t, depth - 1, minDepth - 1) +
           adaptiveSimpson(f, xm, x1, y0, ym, b, t, depth - 1, minDepth - 1) +
           adaptiveSimpson(f, x0, xm, ym, y1, c, t, depth - 1, minDepth - 1) +
           adaptiveSimpson(f, xm, x1, ym, y1, d, t, depth - 1, minDepth - 1);
}

// ---- Text ---------------------------------------------------------------------------------

/// A number as a reader wants it: up to `digits` significant digits, no trailing zeros.
std::string number(double v, int digits = 4) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    return buffer;
}

/// A count with thousands separators: 200,000.
std::string grouped(std::uint64_t n) {
    const std::string digits = std::to_string(n);
    std::string s;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) s += ',';
        s += digits[i];
    }
    return s;
}

/// Text safe inside SVG.
std::string xmlEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

/// A domain edge as a label: 2π and π by name.
std::string edgeLabel(double v) {
    if (std::abs(v - 2.0 * M_PI) < 1e-12) return "2π";
    if (std::abs(v - M_PI) < 1e-12) return "π";
    return number(v, 3);
}

// ---- Colours ------------------------------------------------------------------------------

struct Rgb {
    unsigned char r, g, b;
};

/// Linear interpolation through evenly spaced colour stops, t in [0, 1].
Rgb ramp(const std::vector<Rgb>& stops, double t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (stops.size() - 1);
    const size_t i = std::min(stops.size() - 2, static_cast<size_t>(t));
    const double f = t - i;
    auto mixChannel = [&](unsigned char a, unsigned char b) {
        return static_cast<unsigned char>(std::lround(a + f * (b - a)));
    };
    return {mixChannel(stops[i].r, stops[i + 1].r), mixChannel(stops[i].g, stops[i + 1].g),
            mixChannel(stops[i].b, stops[i + 1].b)};
}

/// Counts: viridis, dark (none) to yellow (the most).
const std::vector<Rgb> kCountColours = {
    {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
/// Differences: blue (too few), white (as expected), red (too many).
const std::vector<Rgb> kDifferenceColours = {{33, 102, 172}, {247, 247, 247}, {178, 24, 43}};
/// The standardised difference shown in full colour.
constexpr double kDifferenceRange = 4.0;

std::string hex(const Rgb& c) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", c.r, c.g, c.b);
    return buffer;
}

/// A kPanel × kPanel PNG of one value per bin (y upwards), coloured by `colour`, as base64.
std::string panelPng(const WarpRun& run, const std::function<Rgb(size_t bin)>& colour) {
    std::vector<unsigned char> pixels(kPanel * kPanel * 3);
    for (int py = 0; py < kPanel; ++py)
        for (int px = 0; px < kPanel; ++px) {
            const int i = px * run.xBins / kPanel;
            const int j = (kPanel - 1 - py) * run.yBins / kPanel;  // y grows upwards
            const Rgb c = colour(static_cast<size_t>(j) * run.xBins + i);
            unsigned char* p = &pixels[(py * kPanel + px) * 3];
            p[0] = c.r, p[1] = c.g, p[2] = c.b;
        }
    std::string png;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
        },
        &png, kPanel, kPanel, 3, pixels.data(), kPanel * 3);
    // Base64, for a data: URI.
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < png.size(); i += 3) {
        const auto byte = [&](size_t k) {
            return k < png.size() ? static_cast<unsigned>(static_cast<unsigned char>(png[k])) : 0u;
        };
        const unsigned v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
        out += table[v >> 18 & 63];
        out += table[v >> 12 & 63];
        out += i + 1 < png.size() ? table[v >> 6 & 63] : '=';
        out += i + 2 < png.size() ? table[v & 63] : '=';
    }
    return out;
}

// ---- Command line -------------------------------------------------------------------------

/// A whole number in [lo, hi] for option `option`.
long long wholeNumber(const std::string& option, const std::string& text, long long lo,
                      long long hi) {
    long long v = 0;
    const auto [end, ec] = rb::fromChars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
        throw InputError("--warptest " + option + ": expected a whole number from " +
                         std::to_string(lo) + " to " + std::to_string(hi) + ", got '" + text + "'");
    return v;
}

/// The list of samplers, for --warptest list and for errors.
std::string warpList(const std::vector<Warp>& warps) {
    std::string text;
    for (const Warp& w : warps) {
        std::string line = "  " + w.name;
        line += std::string(line.size() < 20 ? 20 - line.size() : 1, ' ');
        text += line + "chapter " + std::to_string(w.chapter) +
                (w.exercise.empty() ? "" : ", exercise " + w.exercise) + ": " + w.title + "\n";
        for (const WarpParameter& p : w.parameters)
            text += std::string(22, ' ') + p.name + "=" + number(p.value) + "  " + p.help + " (" +
                    number(p.min) + " to " + number(p.max) + ")\n";
    }
    return text;
}

const char* kUsage =
    "usage: ./rt --warptest NAME [PARAMETER=VALUE ...] [--samples N] [--bins XxY] [--seed S]\n"
    "                        [--output FILE.svg]\n"
    "       ./rt --warptest all [--output-dir DIR]   every sampler, Sidak-corrected\n"
    "       ./rt --warptest list\n"
    "Draws a chapter's sampler many times, bins the points on the sampler's own domain, and\n"
    "tests them against the pdf the code states (chi-square, pooled below 5, alpha = 0.01);\n"
    "writes a figure (observed, expected, difference) and exits 1 when the test fails.\n";

/// The verdict line of a run at level alpha.
std::string verdict(const WarpRun& run, double alpha) {
    if (run.samples == 0) return "FAIL: the sampler drew no points";
    return run.test.pValue > alpha
               ? "PASS: the points fit the pdf (p = " + number(run.test.pValue, 3) + " > " +
                     number(alpha, 3) + ")"
               : "FAIL: the points do not follow the pdf (p = " + number(run.test.pValue, 3) +
                     " <= " + number(alpha, 3) + ")";
}

bool passed(const WarpRun& run, double alpha) {
    return run.samples > 0 && run.test.pValue > alpha;
}

/// The report of one run, for the terminal.
void report(const WarpRun& run, double alpha, std::ostream& out) {
    if (run.samples == 0) {
        out << run.name << " (chapter " << run.chapter
            << (run.exercise.empty() ? "" : ", exercise " + run.exercise) << "): " << run.title
            << "\n  " << run.caption << "\n  " << verdict(run, alpha)
            << (run.exercise.empty() ? "" : ": is exercise " + run.exercise + " written?") << "\n";
        return;
    }
    out << run.name << " (chapter " << run.chapter
        << (run.exercise.empty() ? "" : ", exercise " + run.exercise) << "): " << run.title
        << "\n  " << run.caption << "; " << grouped(run.samples) << " points in " << run.xBins
        << " x " << run.yBins << " bins of (" << run.domain.xLabel << ", " << run.domain.yLabel
        << ")\n  chi-square = " << number(run.test.statistic, 6) << ", " << run.test.dof
        << " degrees of freedom (" << run.test.pooledCells
        << " bins expecting < 5 pooled), p = " << number(run.test.pValue, 3)
        << "\n  outside the domain: " << run.outsideObserved << " observed, "
        << number(run.outsideExpected, 4) << " expected\n  " << verdict(run, alpha) << "\n";
    if (run.samples > 0 && std::isinf(run.test.statistic))
        out << "  Points fell where the pdf is 0 (or off the domain, NaN, or not unit directions):"
               " the sampler leaves the support its pdf states.\n";
    if (!passed(run, alpha))
        out << "  The difference panel shows where: red bins got too many points, blue too few."
            << (run.exercise.empty() ? "" : " Check exercise " + run.exercise + "'s code.") << "\n";
}

}  // namespace

// ---- The lab ------------------------------------------------------------------------------

std::vector<Warp> builtWarps(const std::vector<Feature>& built) {
    std::vector<Warp> warps;
    for (const Feature& f : built)
        if (f.warps)
            for (Warp& w : f.warps()) warps.push_back(std::move(w));
    return warps;
}

double integrate2D(const std::function<double(const Vec2&)>& f, double x0, double x1, double y0,
                   double y1) {
    return adaptiveSimpson(f, x0, x1, y0, y1, simpsonRectangle(f, x0, x1, y0, y1), 1e-10, 9, 2);
}

WarpRun runWarp(const Warp& warp, const std::map<std::string, double>& values,
                const WarpRunSettings& settings) {
    // Check the parameters against the sampler's list; fill in the defaults.
    std::map<std::string, double> all;
    for (const WarpParameter& p : warp.parameters) all[p.name] = p.value;
    for (const auto& [name, value] : values) {
        // clang (make fuzz) cannot capture a structured binding: the lambda sees a copy.
        const auto it =
            std::find_if(warp.parameters.begin(), warp.parameters.end(),
                         [key = name](const WarpParameter& p) { return p.name == key; });
        if (it == warp.parameters.end()) {
            std::string known;
            for (const WarpParameter& p : warp.parameters) known += " " + p.name;
            throw InputError("--warptest " + warp.name + ": no parameter '" + name + "'; " +
                             (known.empty() ? "it has none" : "it has:" + known));
        }
        if (!(value >= it->min && value <= it->max))
            throw InputError("--warptest " + warp.name + ": " + name + " must be from " +
                             number(it->min) + " to " + number(it->max) + ", got " + number(value));
        all[name] = value;
    }
    const WarpSetup setup = warp.setup(all);

    WarpRun run;
    run.name = warp.name;
    run.title = warp.title;
    run.caption = setup.caption;
    run.chapter = warp.chapter;
    run.exercise = warp.exercise;
    run.domain = setup.domain;
    run.xBins = settings.xBins > 0 ? settings.xBins : 24;
    run.yBins = settings.yBins > 0 ? settings.yBins : 24;
    const WarpDomain& d = setup.domain;
    const size_t bins = static_cast<size_t>(run.xBins) * run.yBins;

    // Draw the points.
    std::vector<Vec2> points;
    points.reserve(settings.samples);
    setup.draw(settings.samples, settings.seed, points);
    run.samples = points.size();

    // Bin them; a point within a hair of the domain's edge (rounding) counts as inside.
    run.observed.assign(bins, 0.0);
    const double w = d.x1 - d.x0, h = d.y1 - d.y0;
    for (const Vec2& p : points) {
        const double fx = (p.x - d.x0) / w, fy = (p.y - d.y0) / h;
        if (!(fx >= -1e-9 && fx <= 1.0 + 1e-9 && fy >= -1e-9 && fy <= 1.0 + 1e-9)) {
            run.outsideObserved += 1.0;
            continue;
        }
        const int i = std::clamp(static_cast<int>(fx * run.xBins), 0, run.xBins - 1);
        const int j = std::clamp(static_cast<int>(fy * run.yBins), 0, run.yBins - 1);
        run.observed[static_cast<size_t>(j) * run.xBins + i] += 1.0;
    }

    // Integrate the stated pdf over each bin; what it leaves outside the domain goes to the
    // outside cell.
    run.expected.assign(bins, 0.0);
    double inside = 0.0;
    for (int j = 0; j < run.yBins; ++j)
        for (int i = 0; i < run.xBins; ++i) {
            const double p =
                integrate2D(setup.pdf, d.x0 + w * i / run.xBins, d.x0 + w * (i + 1) / run.xBins,
                            d.y0 + h * j / run.yBins, d.y0 + h * (j + 1) / run.yBins);
            run.expected[static_cast<size_t>(j) * run.xBins + i] = run.samples * p;
            inside += p;
        }
    run.outsideExpected = run.samples * std::max(0.0, 1.0 - inside);

    // The outside is one more cell, unless it is empty and expected to be.
    std::vector<double> observed = run.observed, expected = run.expected;
    if (run.outsideObserved > 0.0 || run.outsideExpected > 0.0) {
        observed.push_back(run.outsideObserved);
        expected.push_back(run.outsideExpected);
    }
    run.test = chiSquareTest(observed, expected);
    if (run.samples == 0) run.test.pValue = 0.0;
    return run;
}

void writeWarpFigure(const WarpRun& run, double alpha, const std::string& path) {
    const bool ok = passed(run, alpha);
    double top = 0.0;
    for (size_t k = 0; k < run.observed.size(); ++k)
        top = std::max({top, run.observed[k], run.expected[k]});
    if (top <= 0.0) top = 1.0;
    const auto countColour = [&](const std::vector<double>& v) {
        return [&v, top](size_t k) { return ramp(kCountColours, v[k] / top); };
    };
    const auto differenceColour = [&](size_t k) {
        const double e = run.expected[k], o = run.observed[k];
        // A point where none is expected is as wrong as it gets.
        const double z = e > 0.0 ? (o - e) / std::sqrt(e) : (o > 0.0 ? kDifferenceRange : 0.0);
        return ramp(kDifferenceColours, 0.5 + 0.5 * z / kDifferenceRange);
    };

    const int left = 60, gap = 70, y0 = 120;
    const int width = left + 3 * kPanel + 2 * gap + 40, height = y0 + kPanel + 100;
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
           "width=\""
        << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << " " << height
        << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<defs><linearGradient id=\"counts\">";
    for (size_t k = 0; k < kCountColours.size(); ++k)
        svg << "<stop offset=\"" << number(double(k) / (kCountColours.size() - 1))
            << "\" stop-color=\"" << hex(kCountColours[k]) << "\"/>";
    svg << "</linearGradient><linearGradient id=\"difference\">";
    for (size_t k = 0; k < kDifferenceColours.size(); ++k)
        svg << "<stop offset=\"" << number(double(k) / (kDifferenceColours.size() - 1))
            << "\" stop-color=\"" << hex(kDifferenceColours[k]) << "\"/>";
    svg << "</linearGradient></defs>\n";

    // The title, the setting and the verdict.
    svg << "<text x=\"" << left << "\" y=\"22\" font-size=\"16\" font-weight=\"bold\">"
        << xmlEscape("./rt --warptest " + run.name + " — chapter " + std::to_string(run.chapter) +
                     (run.exercise.empty() ? "" : ", exercise " + run.exercise))
        << "</text>\n<text x=\"" << left << "\" y=\"42\">" << xmlEscape(run.title)
        << "</text>\n<text x=\"" << left << "\" y=\"60\">"
        << xmlEscape(run.caption + "; " + grouped(run.samples) + " points in " +
                     std::to_string(run.xBins) + " × " + std::to_string(run.yBins) + " bins")
        << "</text>\n<text x=\"" << left << "\" y=\"84\" font-weight=\"bold\" fill=\""
        << (ok ? "#1a7f37" : "#c62828") << "\">"
        << xmlEscape("χ² = " + number(run.test.statistic, 6) + ", " + std::to_string(run.test.dof) +
                     " degrees of freedom, " + verdict(run, alpha))
        << "</text>\n";

    // The three panels.
    const std::string titles[3] = {"observed counts", "expected: points × ∫ pdf over each bin",
                                   "(observed − expected) / √expected"};
    const std::string images[3] = {panelPng(run, countColour(run.observed)),
                                   panelPng(run, countColour(run.expected)),
                                   panelPng(run, differenceColour)};
    for (int k = 0; k < 3; ++k) {
        const int x = left + k * (kPanel + gap);
        svg << "<text x=\"" << x + kPanel / 2 << "\" y=\"" << y0 - 6 << "\" text-anchor=\"middle\">"
            << xmlEscape(titles[k]) << "</text>\n"
            << "<image x=\"" << x << "\" y=\"" << y0 << "\" width=\"" << kPanel << "\" height=\""
            << kPanel << "\" xlink:href=\"data:image/png;base64," << images[k] << "\"/>\n"
            << "<rect x=\"" << x << "\" y=\"" << y0 << "\" width=\"" << kPanel << "\" height=\""
            << kPanel << "\" fill=\"none\" stroke=\"#444\"/>\n";
        // Axes: the domain's edges and names.
        const int below = y0 + kPanel + 15;
        svg << "<text x=\"" << x << "\" y=\"" << below << "\" text-anchor=\"start\">"
            << xmlEscape(edgeLabel(run.domain.x0)) << "</text>"
            << "<text x=\"" << x + kPanel << "\" y=\"" << below << "\" text-anchor=\"end\">"
            << xmlEscape(edgeLabel(run.domain.x1)) << "</text>"
            << "<text x=\"" << x + kPanel / 2 << "\" y=\"" << below << "\" text-anchor=\"middle\">"
            << xmlEscape(run.domain.xLabel) << "</text>\n"
            << "<text x=\"" << x - 4 << "\" y=\"" << y0 + kPanel << "\" text-anchor=\"end\">"
            << xmlEscape(edgeLabel(run.domain.y0)) << "</text>"
            << "<text x=\"" << x - 4 << "\" y=\"" << y0 + 10 << "\" text-anchor=\"end\">"
            << xmlEscape(edgeLabel(run.domain.y1)) << "</text>"
            << "<text transform=\"translate(" << x - 8 << "," << y0 + kPanel / 2
            << ") rotate(-90)\" text-anchor=\"middle\">" << xmlEscape(run.domain.yLabel)
            << "</text>\n";
        // The colour scale.
        const int bar = below + 12;
        svg << "<rect x=\"" << x << "\" y=\"" << bar << "\" width=\"" << kPanel
            << "\" height=\"10\" fill=\"url(#" << (k < 2 ? "counts" : "difference")
            << ")\" stroke=\"#444\" stroke-width=\"0.5\"/>\n";
        const std::string lo = k < 2 ? "0" : "−" + number(kDifferenceRange) + "σ (too few)";
        const std::string hi =
            k < 2 ? number(top, 4) + " points" : "+" + number(kDifferenceRange) + "σ (too many)";
        svg << "<text x=\"" << x << "\" y=\"" << bar + 24 << "\" font-size=\"11\">" << xmlEscape(lo)
            << "</text><text x=\"" << x + kPanel << "\" y=\"" << bar + 24
            << "\" font-size=\"11\" text-anchor=\"end\">" << xmlEscape(hi) << "</text>\n";
    }
    svg << "<text x=\"" << left << "\" y=\"" << height - 14 << "\" font-size=\"12\">"
        << xmlEscape("outside the domain: " + number(run.outsideObserved, 8) + " points, " +
                     number(run.outsideExpected, 4) + " expected; bins expecting fewer than 5 " +
                     "points are pooled (" + std::to_string(run.test.pooledCells) + " here)")
        << "</text>\n</svg>\n";

    const std::string text = svg.str();
    writeImageFile(path, "SVG", [&text](ImageByteSink sink, void* context) {
        sink(context, const_cast<char*>(text.data()), static_cast<int>(text.size()));
        return true;
    });
}

int warpTestCommand(const std::vector<std::string>& args, const std::vector<Feature>& built,
                    std::ostream& out, std::ostream& err) {
    const std::vector<Warp> warps = builtWarps(built);
    try {
        if (args.empty() || args[0] == "--help" || args[0] == "-h") {
            (args.empty() ? err : out) << kUsage << "\nSamplers in this build:\n"
                                       << warpList(warps);
            return args.empty() ? 1 : 0;
        }
        if (args[0] == "list") {
            out << warpList(warps);
            return 0;
        }
        // Parse the options and parameters after the name.
        WarpRunSettings settings;
        std::map<std::string, double> values;
        std::string output, outputDir;
        for (size_t i = 1; i < args.size(); ++i) {
            std::string name = args[i], value;
            const auto eq = name.find('=');
            const bool option = name.rfind("--", 0) == 0;
            if (eq != std::string::npos) {
                value = name.substr(eq + 1);
                name = name.substr(0, eq);
            } else if (option) {
                if (i + 1 >= args.size())
                    throw InputError("--warptest " + name + ": missing value");
                value = args[++i];
            } else {
                throw InputError("--warptest: expected PARAMETER=VALUE or an option, got '" + name +
                                 "'");
            }
            if (name == "--samples")
                settings.samples =
                    static_cast<std::uint64_t>(wholeNumber(name, value, 1, 100000000));
            else if (name == "--seed")
                settings.seed = static_cast<std::uint64_t>(wholeNumber(name, value, 0, 1LL << 62));
            else if (name == "--bins") {
                const auto x = value.find('x');
                if (x == std::string::npos)
                    throw InputError("--warptest --bins: expected XxY, got '" + value + "'");
                settings.xBins = static_cast<int>(wholeNumber(name, value.substr(0, x), 1, 512));
                settings.yBins = static_cast<int>(wholeNumber(name, value.substr(x + 1), 1, 512));
            } else if (name == "--output" || name == "-o") {
                output = value;
                if (output.size() < 4 || output.substr(output.size() - 4) != ".svg")
                    throw InputError(
                        "--warptest --output: the figure is SVG; name a .svg file, "
                        "got '" +
                        output + "'");
            } else if (name == "--output-dir")
                outputDir = value;
            else if (option)
                throw InputError("--warptest: unknown option " + name +
                                 " (options: --samples, --bins, --seed, --output, --output-dir)");
            else {
                double v = 0.0;
                const auto [end, ec] = rb::fromChars(value.data(), value.data() + value.size(), v);
                if (ec != std::errc() || end != value.data() + value.size() || !std::isfinite(v))
                    throw InputError("--warptest: " + name + " must be a number, got '" + value +
                                     "'");
                values[name] = v;
            }
        }

        // Every sampler at once: the check CTest runs, and the figures of the chapter pages.
        if (args[0] == "all") {
            if (!values.empty())
                throw InputError(
                    "--warptest all runs every sampler with its defaults; give "
                    "parameters to one sampler by name");
            const double alpha = sidak(kAlpha, static_cast<int>(std::max<size_t>(1, warps.size())));
            if (!outputDir.empty()) {
                std::error_code ec;
                std::filesystem::create_directories(outputDir, ec);
                if (ec)
                    throw InputError("--warptest --output-dir: cannot create " + outputDir + ": " +
                                     ec.message());
            }
            out << "Every sampler in this build, at alpha = " << kAlpha << " Sidak-corrected for "
                << warps.size() << " tests: " << number(alpha, 4) << " each\n\n";
            int failures = 0;
            for (const Warp& w : warps) {
                // A stub that is still in place (rb::ExerciseNotDone) fails its sampler only.
                WarpRun run;
                try {
                    run = runWarp(w, {}, settings);
                } catch (const std::logic_error& e) {
                    out << w.name << " (chapter " << w.chapter << "): FAIL: " << e.what() << "\n\n";
                    ++failures;
                    continue;
                }
                report(run, alpha, out);
                if (!outputDir.empty()) {
                    char file[32];
                    std::snprintf(file, sizeof file, "ch%02d-lab-", run.chapter);
                    const std::string path =
                        (std::filesystem::path(outputDir) / (file + run.name + ".svg")).string();
                    writeWarpFigure(run, alpha, path);
                    out << "  figure: " << path << "\n";
                }
                out << "\n";
                if (!passed(run, alpha)) ++failures;
            }
            out << (failures == 0 ? "all " + std::to_string(warps.size()) + " samplers pass"
                                  : std::to_string(failures) + " of " +
                                        std::to_string(warps.size()) + " samplers FAIL")
                << "\n";
            return failures == 0 ? 0 : 1;
        }

        // One sampler.
        const auto it = std::find_if(warps.begin(), warps.end(),
                                     [&](const Warp& w) { return w.name == args[0]; });
        if (it == warps.end()) {
            std::string names;
            for (const Warp& w : warps)
                names +=
                    (names.empty() ? "" : ", ") + w.name + " (" + std::to_string(w.chapter) + ")";
            throw InputError("--warptest: no sampler named '" + args[0] +
                             "' in this build; the samplers (chapter) are: " +
                             (names.empty() ? "none before chapter 6" : names) +
                             ". ./rt --warptest list shows their parameters");
        }
        const WarpRun run = runWarp(*it, values, settings);
        report(run, kAlpha, out);
        if (output.empty()) output = "warptest-" + run.name + ".svg";
        if (!outputDir.empty())
            output = (std::filesystem::path(outputDir) / std::filesystem::path(output).filename())
                         .string();
        writeWarpFigure(run, kAlpha, output);
        out << "  figure: " << output << "\n";
        return passed(run, kAlpha) ? 0 : 1;
    } catch (const InputError& e) {
        err << "rt: error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace rb
