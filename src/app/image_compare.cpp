/// \file
/// Golden-image comparison: implementation (see image_compare.h).
#include "app/image_compare.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "core/from_chars.h"

namespace rb::golden {

namespace {

/// s without leading and trailing blanks.
std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

/// Parses all of `text` as a number of type T; false when anything is left over.
template <typename T>
bool parse_number(std::string_view text, T& value) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = rb::fromChars(text.data(), end, value);
    return ec == std::errc() && ptr == end && !text.empty();
}

/// v with `digits` significant digits, trailing zeros dropped ("%g").
std::string format_sig(double v, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    return buffer;
}

}  // namespace

Image Image::filled(int w, int h, float r, float g, float b) {
    Image image{w, h, {}};
    image.rgb.resize(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        image.rgb[i] = r;
        image.rgb[i + 1] = g;
        image.rgb[i + 2] = b;
    }
    return image;
}

namespace {

/// Most pixels rt --compare reads from an image (8192 × 8192; the float copy takes 768 MiB).
/// A file of a few bytes can declare a far larger one, which stb would allocate before
/// reading a pixel.
constexpr long long kMaxComparePixels = 1LL << 26;

/// The 8 bytes every PNG file starts with.
constexpr char kPngSignature[] = "\x89PNG\r\n\x1a\n";

/// Why a file could not be opened for reading, in words; `error` is errno after the attempt.
std::string why_unopened(const std::filesystem::path& path, int error) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) return "there is no such file";
    if (std::filesystem::is_directory(status)) return "it is a folder, not a file";
    return std::string("it cannot be opened: ") + std::strerror(error);
}

}  // namespace

Image load_png(const std::filesystem::path& path) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    // A folder opens as a stream on Linux and fails only when read
    if (!in || std::filesystem::is_directory(path)) {
        const int error = errno;
        throw std::runtime_error("cannot read image " + path.string() + ": " +
                                 why_unopened(path, error));
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return decode_png(bytes, path.string());
}

Image decode_png(const std::string& bytes, const std::string& source) {
    const auto fail = [&](const std::string& why) {
        throw std::runtime_error("cannot read image " + source + ": " + why);
    };
    // stb also reads GIF, BMP, PSD, PNM and more; only PNG reaches it, which keeps those readers'
    // bugs out of reach (stb 2.27's PNM header overflows an int, found by fuzz_compare)
    if (bytes.compare(0, 8, kPngSignature, 8) != 0) fail("not a PNG file");
    if (bytes.size() > std::size_t{std::numeric_limits<int>::max()}) fail("over 2 GiB");
    // Each chunk up to IEND (length, type, data, CRC) must fit in the file: stb grows its buffer
    // to a chunk's declared length before it reads the data (2 GiB for an 82-byte file, found
    // by fuzz_compare)
    for (std::size_t at = 8; bytes.size() - at >= 8 && bytes.compare(at + 4, 4, "IEND") != 0;) {
        const auto byte = [&](std::size_t i) { return std::uint32_t(std::uint8_t(bytes[at + i])); };
        const std::uint32_t length = byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
        if (std::size_t{length} + 12 > bytes.size() - at)
            fail("a chunk declares " + std::to_string(length) + " bytes, more than the file has");
        at += 12 + std::size_t{length};
    }
    const auto* begin = reinterpret_cast<const unsigned char*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels_in_file = 0;
    if (stbi_info_from_memory(begin, size, &w, &h, &channels_in_file) &&
        (w > kMaxSide || h > kMaxSide || static_cast<long long>(w) * h > kMaxComparePixels)) {
        fail("its header declares " + std::to_string(w) + "x" + std::to_string(h) +
             " pixels, more than rt --compare reads (" + std::to_string(kMaxSide) + " a side, " +
             std::to_string(kMaxComparePixels) + " in all)");
    }

    // Let stb convert grey and RGBA to 8-bit RGB; renders are opaque, so alpha is dropped
    std::unique_ptr<unsigned char, void (*)(void*)> data(
        stbi_load_from_memory(begin, size, &w, &h, &channels_in_file, 3), stbi_image_free);
    if (!data) {
        // stb's reasons are terse ("bad zlib header", "corrupt"): say what they mean first
        const char* why = stbi_failure_reason();
        fail(std::string("its PNG data is damaged or of a kind rt cannot decode (stb_image: ") +
             (why ? why : "no reason given") + ")");
    }

    // Convert to float in [0, 1]
    Image image{w, h, {}};
    const std::size_t count = 3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    image.rgb.resize(count);
    for (std::size_t i = 0; i < count; ++i) image.rgb[i] = data.get()[i] / 255.0f;
    return image;
}

void save_png(const std::filesystem::path& path, const Image& image) {
    // Quantise to 8 bits; NaN becomes 0 so a broken image still writes
    std::vector<unsigned char> bytes(image.rgb.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const float v = image.rgb[i];
        const float clamped = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
        bytes[i] = static_cast<unsigned char>(std::lround(clamped * 255.0f));
    }
    if (!stbi_write_png(path.c_str(), image.w, image.h, 3, bytes.data(), 3 * image.w))
        throw std::runtime_error("cannot write PNG " + path.string());
}

Thresholds parse_thresholds(std::istream& in, const std::string& source_name) {
    Thresholds t;
    std::set<std::string, std::less<>> seen;
    std::string raw_line;
    int line_number = 0;
    while (std::getline(in, raw_line)) {
        ++line_number;
        const auto fail = [&](const std::string& what) {
            throw std::runtime_error(source_name + ":" + std::to_string(line_number) + ": " + what);
        };

        // Drop the comment, then split into key and the rest of the line
        std::string_view line = raw_line;
        line = trim(line.substr(0, line.find('#')));
        if (line.empty()) continue;
        const auto key_end = std::min(line.find_first_of(" \t"), line.size());
        const std::string key(line.substr(0, key_end));
        const std::string_view value = trim(line.substr(key_end));
        if (!seen.insert(key).second) fail("'" + key + "' is given twice");
        const auto expect = [&](bool ok, const char* what) {
            if (!ok)
                fail("expected " + std::string(what) + " after '" + key + "', got '" +
                     std::string(value) + "'");
        };

        // Interpret the value by key
        if (key == "args") {
            t.extra_args = std::string(value);
        } else if (key == "size") {
            const auto x = value.find('x');
            const bool ok = x != std::string_view::npos &&
                            parse_number(value.substr(0, x), t.width) &&
                            parse_number(value.substr(x + 1), t.height) && t.width > 0 &&
                            t.height > 0 && t.width <= kMaxSide && t.height <= kMaxSide;
            expect(ok, "WIDTHxHEIGHT such as 192x144");
        } else if (key == "seed") {
            expect(parse_number(value, t.seed), "an unsigned integer");
        } else if (key == "rmse") {
            expect(parse_number(value, t.rmse) && t.rmse >= 0 && std::isfinite(t.rmse),
                   "a number >= 0");
        } else if (key == "pixel_tol") {
            expect(parse_number(value, t.pixel_tol) && t.pixel_tol >= 0 && t.pixel_tol <= 1,
                   "a number in [0, 1]");
        } else if (key == "max_fraction") {
            expect(
                parse_number(value, t.max_fraction) && t.max_fraction >= 0 && t.max_fraction <= 1,
                "a fraction in [0, 1] (0.002 means 0.2%)");
        } else {
            fail("unknown key '" + key +
                 "' (expected size, seed, rmse, pixel_tol, max_fraction or args)");
        }
    }
    return t;
}

Thresholds load_thresholds(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open thresholds file " + path.string());
    return parse_thresholds(in, path.string());
}

Comparison compare(const Image& expected, const Image& actual, const Thresholds& thresholds) {
    Comparison result;

    // A size mismatch means the metric cannot run: fail with the reason
    if (expected.w != actual.w || expected.h != actual.h) {
        result.rmse = std::numeric_limits<double>::infinity();
        result.psnr = -std::numeric_limits<double>::infinity();
        result.outlier_fraction = 1.0;
        result.max_diff = 1.0;
        result.size_mismatch = true;
        result.reason = "image size " + std::to_string(actual.w) + "x" + std::to_string(actual.h) +
                        " differs from golden " + std::to_string(expected.w) + "x" +
                        std::to_string(expected.h);
        return result;
    }

    // Accumulate squared differences and count outlier pixels
    double sum_squared = 0.0;
    for (int y = 0; y < expected.h; ++y) {
        for (int x = 0; x < expected.w; ++x) {
            double pixel_max = 0.0;
            bool pixel_nan = false;
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(double(actual.at(x, y, c)) - expected.at(x, y, c));
                sum_squared += d * d;
                pixel_nan = pixel_nan || std::isnan(d);
                pixel_max = std::max(pixel_max, d);
            }
            // Why `!(<=)`: a NaN channel counts as an outlier, never as a match
            if (pixel_nan || !(pixel_max <= thresholds.pixel_tol)) ++result.outlier_count;
            result.max_diff = std::max(result.max_diff, pixel_nan ? 1.0 : pixel_max);
        }
    }

    // Turn the sums into the metrics
    result.pixel_count =
        static_cast<std::size_t>(expected.w) * static_cast<std::size_t>(expected.h);
    const double n = std::max<double>(1.0, static_cast<double>(result.pixel_count));
    result.rmse = std::sqrt(sum_squared / (3.0 * n));
    result.psnr = result.rmse > 0 ? 20.0 * std::log10(1.0 / result.rmse)
                                  : std::numeric_limits<double>::infinity();
    result.outlier_fraction = static_cast<double>(result.outlier_count) / n;
    result.passed =
        result.rmse <= thresholds.rmse && result.outlier_fraction <= thresholds.max_fraction;
    return result;
}

std::string format_against(double v, double limit) {
    // Add digits until the value no longer prints equal to a limit it differs from
    std::string text = format_sig(v, 3);
    for (int digits = 4; digits <= 12 && v != limit && text == format_sig(limit, 12); ++digits)
        text = format_sig(v, digits);
    return text;
}

std::string describe(const Comparison& c, const Thresholds& t) {
    if (c.size_mismatch) return c.reason;

    // RMSE against its threshold
    const bool rmse_ok = c.rmse <= t.rmse;
    std::string text = "RMSE " + format_against(c.rmse, t.rmse) + (rmse_ok ? " <= " : " > ") +
                       format_sig(t.rmse, 12);

    // Outlier share against the allowed share, in percent
    const std::string percent = format_against(100.0 * c.outlier_fraction, 100.0 * t.max_fraction);
    const std::string allowed = format_sig(100.0 * t.max_fraction, 12);
    text += "; " + percent + "% of pixels beyond " + format_sig(t.pixel_tol, 12);
    text += c.passed ? ", allowed " + allowed + "%" : " (allowed " + allowed + "%)";
    return text;
}

Image diff_image(const Image& expected, const Image& actual, double pixel_tol, double magnify) {
    // Cover both images; pixels missing from either stay magenta
    const int w = std::max(expected.w, actual.w);
    const int h = std::max(expected.h, actual.h);
    Image diff = Image::filled(w, h, 1.0f, 0.0f, 1.0f);
    const int common_w = std::min(expected.w, actual.w);
    const int common_h = std::min(expected.h, actual.h);

    for (int y = 0; y < common_h; ++y) {
        for (int x = 0; x < common_w; ++x) {
            // Magnify the per-channel difference
            double pixel_max = 0.0;
            bool pixel_nan = false;
            float magnified[3];
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(double(actual.at(x, y, c)) - expected.at(x, y, c));
                pixel_nan = pixel_nan || std::isnan(d);
                pixel_max = std::max(pixel_max, d);
                magnified[c] = static_cast<float>(std::min(1.0, d * magnify));
            }
            // Outliers stay magenta, exactly as compare() counts them
            if (pixel_nan || !(pixel_max <= pixel_tol)) continue;
            for (int c = 0; c < 3; ++c) diff.at(x, y, c) = magnified[c];
        }
    }
    return diff;
}

}  // namespace rb::golden
