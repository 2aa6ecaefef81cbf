/// \file
/// The command `rt --compare` compares two images and prints RMSE, PSNR, the largest difference and
/// the share of pixels more than one 8-bit level apart; with a golden image's thresholds file it is
/// the golden check itself (the golden tests, make check and make grade run it), and on failure
/// writes an HTML report (expected, actual and magnified difference side by side).
#include "app/compare.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "app/block_stats.h"
#include "app/html.h"
#include "app/image_compare.h"
#include "core/error.h"
#include "core/render_context.h"

namespace fs = std::filesystem;
using namespace rb::golden;

namespace {

/// Displayed width (CSS pixels) that the report aims for per image.
constexpr int kTargetDisplayWidth = 384;

/// One 8-bit level. A pixel is "over one level" when a channel differs by two levels or more;
/// the tolerance sits between one and two levels, so float rounding cannot move a pixel across.
constexpr double kOneLevelTolerance = 1.5 / 255.0;

/// The command line of ./rt --compare.
struct Options {
    fs::path expected;     ///< First image: the reference (a golden image).
    fs::path actual;       ///< Second image: the render being judged.
    fs::path diff;         ///< --diff D.png: write the difference picture there.
    double threshold = 0;  ///< --threshold RMSE: the largest RMSE that passes (plain mode).
    fs::path thresholds;   ///< --thresholds NAME.txt: a golden image's thresholds (golden mode).
    std::string name;      ///< --name: prefixes the verdict and names the report files.
    fs::path report_dir;   ///< --report-dir DIR: failure reports and index.html go there.
    fs::path stats;        ///< --stats NAME.stats: the statistical check (golden mode).
};

constexpr const char* kUsage =
    "usage: rt --compare EXPECTED.png ACTUAL.png [--diff DIFF.png] [--threshold RMSE]\n"
    "       rt --compare GOLDEN.png RENDER.png --thresholds NAME.txt [--name NAME]\n"
    "                    [--report-dir DIR] [--stats NAME.stats]\n"
    "Prints RMSE, PSNR, the largest channel difference and the share of pixels more than one\n"
    "8-bit level apart; exits 0 when RMSE <= --threshold (default 0: the same pixels), else 1.\n"
    "With --thresholds it is the golden check of make test, make check and make grade: it\n"
    "passes or fails against that file's limits (and, with --stats, statistically), and\n"
    "writes an HTML report of a failure into --report-dir.\n";

/// --threshold's value: a number >= 0, or InputError naming the option.
double parse_threshold(const std::string& text) {
    const double v = rb::parseNumberOption("--threshold", text);
    if (v < 0) throw rb::InputError("--threshold: expected a number >= 0, got '" + text + "'");
    return v;
}

/// Parses the arguments after --compare; throws runtime_error on a mistake.
Options parse_options(const std::vector<std::string>& args) {
    Options o;
    std::vector<std::string> images;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i];
        if (arg.rfind("--", 0) != 0) {
            images.push_back(arg);
            continue;
        }
        // Both --key=value and --key value
        std::string value;
        if (const auto eq = arg.find('='); eq != std::string::npos) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
        } else if (i + 1 < args.size()) {
            value = args[++i];
        } else {
            throw std::runtime_error("missing value after " + arg);
        }
        if (arg == "--diff")
            o.diff = value;
        else if (arg == "--threshold")
            o.threshold = parse_threshold(value);
        else if (arg == "--thresholds")
            o.thresholds = value;
        else if (arg == "--name")
            o.name = value;
        else if (arg == "--report-dir")
            o.report_dir = value;
        else if (arg == "--stats")
            o.stats = value;
        else
            throw std::runtime_error("unknown option " + arg);
    }
    if (images.size() != 2)
        throw std::runtime_error("expected two images, EXPECTED.png and ACTUAL.png; got " +
                                 std::to_string(images.size()));
    o.expected = images[0];
    o.actual = images[1];
    if (o.thresholds.empty() && (!o.name.empty() || !o.report_dir.empty() || !o.stats.empty()))
        throw std::runtime_error("--name, --report-dir and --stats need --thresholds NAME.txt");
    if (o.name.empty()) o.name = o.actual.stem().string();
    // The name becomes part of file names in the report directory
    if (o.name.find_first_of("/\\") != std::string::npos || o.name == "index")
        throw std::runtime_error("--name must be a plain file name other than 'index'");
    return o;
}

/// Reverses html_escape (only the entities it produces).
std::string html_unescape(const std::string& text) {
    static const std::pair<std::string_view, char> kEntities[] = {
        {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&#39;", '\''}, {"&amp;", '&'}};
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        // Replace an entity at i, or copy one character
        const auto entity = std::find_if(
            std::begin(kEntities), std::end(kEntities),
            [&](const auto& e) { return text.compare(i, e.first.size(), e.first) == 0; });
        if (entity != std::end(kEntities)) {
            out += entity->second;
            i += entity->first.size();
        } else {
            out += text[i++];
        }
    }
    return out;
}

/// A sibling name for a temporary file that no other process uses (`X.tmp.PID`).
fs::path temp_path_for(const fs::path& path) {
    return path.string() + ".tmp." + std::to_string(::getpid());
}

/// Writes a text file through a temporary file and a rename, so readers never see half a file.
void write_text_atomically(const fs::path& path, const std::string& contents) {
    const fs::path temp = temp_path_for(path);
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << contents;
        if (!out.flush()) throw std::runtime_error("cannot write " + temp.string());
    }
    fs::rename(temp, path);
}

/// Writes a PNG through a temporary file and a rename.
void save_png_atomically(const fs::path& path, const Image& image) {
    const fs::path temp = temp_path_for(path);
    save_png(temp, image);
    fs::rename(temp, path);
}

/// Copies a file byte for byte through a temporary file and a rename.
void copy_atomically(const fs::path& from, const fs::path& to) {
    const fs::path temp = temp_path_for(to);
    fs::copy_file(from, temp, fs::copy_options::overwrite_existing);
    fs::rename(temp, to);
}

/// The report files that the golden check writes for one test name.
std::vector<fs::path> report_files(const fs::path& dir, const std::string& name) {
    return {dir / (name + "-expected.png"), dir / (name + "-actual.png"),
            dir / (name + "-diff.png"), dir / (name + ".html")};
}

/// "W x H" as text.
std::string size_text(const Image& image) {
    return std::to_string(image.w) + "x" + std::to_string(image.h);
}

/// A number with printf formatting.
std::string fmt(const char* format, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

/// One `<figure>` showing an image upscaled by an integer factor with crisp pixels.
std::string figure(const std::string& src, const Image& image, int scale, const std::string& alt,
                   const std::string& caption_html) {
    std::ostringstream html;
    html << "<figure><img src=\"" << rb::escapeHtml(src) << "\" width=\"" << image.w * scale
         << "\" height=\"" << image.h * scale << "\" alt=\"" << rb::escapeHtml(alt) << "\">"
         << "<figcaption>" << caption_html << "</figcaption></figure>\n";
    return html.str();
}

/// The per-test HTML page: verdict, the three images side by side, and the numbers.
std::string report_page(const Options& o, const Thresholds& t, const Comparison& c,
                        const std::string& summary, const Image& expected, const Image& actual,
                        const Image& diff) {
    // Upscale by an integer factor so each image is roughly kTargetDisplayWidth wide
    const int scale =
        std::max(1, kTargetDisplayWidth / std::max(1, std::max(expected.w, actual.w)));
    const std::string name = rb::escapeHtml(o.name);
    const auto verdict = [](bool ok) {
        return ok ? "<td>ok</td>" : "<td class=\"fail\">FAIL</td>";
    };

    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         << "<meta name=\"rb-summary\" content=\"" << rb::escapeHtml(summary) << "\">\n"
         << "<title>" << name << ": golden-image failure</title>\n"
         << "<style>\n"
         << "body { font-family: sans-serif; margin: 1.5em; }\n"
         << ".row { display: flex; flex-wrap: wrap; gap: 1.5em; align-items: flex-start; }\n"
         << "figure { margin: 0; }\n"
         << "figure img { image-rendering: crisp-edges; image-rendering: pixelated; "
            "border: 1px solid #888; display: block; }\n"
         << "figcaption { font-size: 90%; margin-top: .3em; }\n"
         << "table { border-collapse: collapse; margin-top: 1.5em; }\n"
         << "th, td { padding: .25em .9em; text-align: left; border-bottom: 1px solid #ddd; }\n"
         << ".fail { color: #b00; font-weight: bold; }\n"
         << "code { background: #f3f3f3; padding: 0 .2em; }\n"
         << "</style>\n</head>\n<body>\n"
         << "<p><a href=\"index.html\">&larr; all golden-image failures</a></p>\n"
         << "<h1>" << name << "</h1>\n"
         << "<p class=\"fail\">FAIL: " << rb::escapeHtml(summary) << "</p>\n";

    // The three images side by side
    html << "<div class=\"row\">\n"
         << figure(o.name + "-expected.png", expected, scale, "expected",
                   "expected (golden, " + size_text(expected) + ")")
         << figure(o.name + "-actual.png", actual, scale, "actual",
                   "actual (this build, " + size_text(actual) + ")")
         << figure(o.name + "-diff.png", diff, scale, "difference",
                   "|actual &minus; expected| &times;8; <span style=\"color:#c0c\">magenta</span>"
                   ": beyond pixel_tol" +
                       std::string(c.size_mismatch ? " or outside one image" : ""))
         << "</div>\n";

    // The numbers against their thresholds
    html << "<table>\n<tr><th>measure</th><th>measured</th><th>allowed</th><th></th></tr>\n";
    if (c.size_mismatch) {
        html << "<tr><td>image size</td><td>" << size_text(actual) << "</td><td>"
             << size_text(expected) << " (golden)</td>" << verdict(false) << "</tr>\n";
    } else {
        html << "<tr><td>RMSE (all channels, all pixels)</td><td>" << format_against(c.rmse, t.rmse)
             << "</td><td>&le; " << fmt("%g", t.rmse) << "</td>" << verdict(c.rmse <= t.rmse)
             << "</tr>\n"
             << "<tr><td>pixels with a channel off by more than pixel_tol "
             << fmt("%g", t.pixel_tol) << "</td><td>"
             << format_against(100 * c.outlier_fraction, 100 * t.max_fraction) << "% ("
             << c.outlier_count << " of " << c.pixel_count << ")</td><td>&le; "
             << fmt("%g", 100 * t.max_fraction) << "%</td>"
             << verdict(c.outlier_fraction <= t.max_fraction) << "</tr>\n"
             << "<tr><td>PSNR</td><td>"
             << (std::isinf(c.psnr) ? std::string("&infin;") : fmt("%.1f", c.psnr))
             << " dB</td><td></td><td></td></tr>\n"
             << "<tr><td>largest channel difference</td><td>" << fmt("%.3g", c.max_diff)
             << "</td><td></td><td></td></tr>\n";
    }
    html << "</table>\n";

    // Where everything came from, and what to do next
    html << "<p>Render settings from <code>" << rb::escapeHtml(o.thresholds.string())
         << "</code>: size " << t.width << "x" << t.height << ", seed " << t.seed
         << (t.extra_args.empty() ? std::string()
                                  : ", args <code>" + rb::escapeHtml(t.extra_args) + "</code>")
         << ".<br>Golden image <code>" << rb::escapeHtml(o.expected.string())
         << "</code>; render <code>" << rb::escapeHtml(o.actual.string()) << "</code>.</p>\n"
         << "<p>If the change is intended, run <code>make golden-update</code> and say in the "
            "commit message why the image changed.</p>\n"
         << "</body>\n</html>\n";
    return html.str();
}

/// The summary stored in a report page's rb-summary meta tag, or "" when absent.
std::string read_summary(const fs::path& page) {
    std::ifstream in(page);
    const std::string marker = "<meta name=\"rb-summary\" content=\"";
    for (std::string line; std::getline(in, line);) {
        if (const auto at = line.find(marker); at != std::string::npos) {
            const auto begin = at + marker.size();
            return html_unescape(line.substr(begin, line.find('"', begin) - begin));
        }
    }
    return "";
}

/// Holds an exclusive flock on DIR/.index.lock while alive (best effort: no lock, no wait).
class IndexLock {
  public:
    /// Takes the lock, waiting for other rt --compare processes to finish their index.
    explicit IndexLock(const fs::path& dir)
        : fd_(::open((dir / ".index.lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {
        if (fd_ >= 0) ::flock(fd_, LOCK_EX);
    }
    ~IndexLock() {
        if (fd_ >= 0) ::close(fd_);  // closing releases the lock
    }
    IndexLock(const IndexLock&) = delete;
    IndexLock& operator=(const IndexLock&) = delete;

  private:
    int fd_;
};

/// Rewrites DIR/index.html to link every NAME.html in DIR, under a lock so parallel tests
/// cannot drop each other's entries.
void rewrite_index(const fs::path& dir) {
    const IndexLock lock(dir);

    // Collect the report pages present now
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const fs::path& p = entry.path();
        if (entry.is_regular_file() && p.extension() == ".html" && p.filename() != "index.html")
            names.push_back(p.stem().string());
    }
    std::sort(names.begin(), names.end());

    // Write the page
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         << "<title>Golden-image failures</title>\n"
         << "<style>body { font-family: sans-serif; margin: 1.5em; } li { margin: .4em 0; }"
         << " .ok { color: #070; }</style>\n</head>\n<body>\n<h1>Golden-image failures</h1>\n";
    if (names.empty()) {
        html << "<p class=\"ok\">No failures: every golden image compared in this directory "
                "passed.</p>\n";
    } else {
        html << "<p>" << names.size()
             << (names.size() == 1 ? " scene differs from its golden image."
                                   : " scenes differ from their golden images.")
             << " If a change is intended, run <code>make "
                "golden-update</code> and say why in the commit message.</p>\n<ul>\n";
        for (const auto& name : names) {
            html << "<li><a href=\"" << rb::escapeHtml(name) << ".html\">" << rb::escapeHtml(name)
                 << "</a>: " << rb::escapeHtml(read_summary(dir / (name + ".html"))) << "</li>\n";
        }
        html << "</ul>\n";
    }
    html << "</body>\n</html>\n";
    write_text_atomically(dir / "index.html", html.str());
}

/// The golden check: the comparison against a golden image's thresholds file (and, with
/// --stats, its block statistics); a failure's report goes to --report-dir. Prints one line.
int golden_check(const Options& o, std::ostream& out) {
    const auto error_line = [&](const std::string& what) {
        // Why the cleanup: a report from an earlier run would describe images not compared now
        std::error_code ignored;
        if (!o.report_dir.empty()) {
            for (const auto& stale : report_files(o.report_dir, o.name)) fs::remove(stale, ignored);
            try {
                if (fs::is_directory(o.report_dir)) rewrite_index(o.report_dir);
            } catch (const std::exception&) {
                // Best effort: the verdict line below is what matters
            }
        }
        out << o.name << ": FAIL: " << what << std::endl;
        return 1;
    };

    // Load the thresholds and both images
    Thresholds thresholds;
    Image expected, actual;
    try {
        thresholds = load_thresholds(o.thresholds);
    } catch (const std::exception& e) {
        return error_line(e.what());
    }
    if (!fs::exists(o.expected))
        return error_line("no golden image " + o.expected.string() + "; run make golden-update");
    try {
        expected = load_png(o.expected);
        actual = load_png(o.actual);
    } catch (const std::exception& e) {
        return error_line(e.what());
    }

    // Compare: the same bits (within the thresholds), or else, with --stats, the same estimate
    Comparison comparison = compare(expected, actual, thresholds);
    std::string summary = describe(comparison, thresholds);
    if (!comparison.passed && !comparison.size_mismatch && !o.stats.empty()) {
        StatisticalComparison statistical;
        try {
            statistical = compare_statistically(load_block_stats(o.stats), actual);
        } catch (const std::exception& e) {
            return error_line(e.what());
        }
        summary = "not raybook's bits (" + summary + "), " + describe(statistical);
        comparison.passed = statistical.passed;
    }

    // Write or clear this test's report, then refresh the index
    if (!o.report_dir.empty()) {
        try {
            fs::create_directories(o.report_dir);
            if (comparison.passed) {
                for (const auto& stale : report_files(o.report_dir, o.name)) fs::remove(stale);
            } else {
                const Image diff = diff_image(expected, actual, thresholds.pixel_tol);
                const auto files = report_files(o.report_dir, o.name);
                copy_atomically(o.expected, files[0]);
                copy_atomically(o.actual, files[1]);
                save_png_atomically(files[2], diff);
                write_text_atomically(files[3], report_page(o, thresholds, comparison, summary,
                                                            expected, actual, diff));
            }
            rewrite_index(o.report_dir);
        } catch (const std::exception& e) {
            return error_line("cannot write the report in " + o.report_dir.string() + ": " +
                              e.what());
        }
    }

    // Print the verdict line
    if (comparison.passed) {
        out << o.name << ": ok (" << summary << ")" << std::endl;
        return 0;
    }
    out << o.name << ": FAIL: " << summary;
    if (!o.report_dir.empty()) out << "; see " << (o.report_dir / "index.html").string();
    out << std::endl;
    return 1;
}

/// Two images, any two: the numbers, the difference picture with --diff, and the verdict
/// against --threshold.
int plain_compare(const Options& o, std::ostream& out) {
    const Image expected = load_png(o.expected), actual = load_png(o.actual);
    Thresholds t;
    t.rmse = o.threshold;
    t.pixel_tol = kOneLevelTolerance;
    t.max_fraction = 1.0;  // only the RMSE decides
    const Comparison c = compare(expected, actual, t);
    if (!o.diff.empty()) save_png(o.diff, diff_image(expected, actual, t.pixel_tol));
    out << o.expected.string() << " against " << o.actual.string();
    if (c.size_mismatch) {
        out << ": the sizes differ, " << size_text(expected) << " and " << size_text(actual)
            << (o.diff.empty() ? "" : "; the difference picture shows both") << std::endl;
        return 1;
    }
    out << ", " << size_text(expected) << ":\n"
        << "  RMSE      " << fmt("%.6g", c.rmse) << " (all channels of all pixels, in [0, 1])\n"
        << "  PSNR      " << (std::isinf(c.psnr) ? std::string("inf") : fmt("%.2f", c.psnr))
        << " dB\n"
        << "  largest   " << fmt("%.6g", c.max_diff) << " (" << fmt("%.0f", c.max_diff * 255.0)
        << " of 255 levels)\n"
        << "  over one level  " << fmt("%.4g", 100.0 * c.outlier_fraction) << "% of pixels ("
        << c.outlier_count << " of " << c.pixel_count << ")\n";
    if (!o.diff.empty())
        out << "  difference picture " << o.diff.string()
            << " (|difference| x 8; magenta: over one level)\n";
    const bool same = c.rmse <= o.threshold;
    out << (same ? "same" : "DIFFERENT") << ": RMSE " << format_against(c.rmse, o.threshold)
        << (same ? " <= " : " > ") << fmt("%g", o.threshold) << " (--threshold)" << std::endl;
    return same ? 0 : 1;
}

}  // namespace

namespace rb {

int compareCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (std::find(args.begin(), args.end(), "--help") != args.end() ||
        std::find(args.begin(), args.end(), "-h") != args.end()) {
        out << kUsage;
        return 0;
    }
    Options o;
    try {
        o = parse_options(args);
    } catch (const std::exception& e) {
        err << "rt: error: --compare: " << e.what() << "\n" << kUsage;
        return 1;
    }
    try {
        return o.thresholds.empty() ? plain_compare(o, out) : golden_check(o, out);
    } catch (const std::exception& e) {
        err << "rt: error: --compare: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace rb
