/// \file
/// Golden-image comparison: PNG input/output, thresholds files, the RMSE-plus-outliers metric
/// and the magnified diff image.
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rb::golden {

/// An RGB image with float channels (nominally in [0, 1]), stored row by row from the top.
struct Image {
    int w = 0;               ///< Width in pixels.
    int h = 0;               ///< Height in pixels.
    std::vector<float> rgb;  ///< 3 * w * h channel values: r, g, b of pixel (0,0), then (1,0), ...

    /// A w x h image filled with the colour (r, g, b).
    static Image filled(int w, int h, float r, float g, float b);
    /// Channel c (0 = r, 1 = g, 2 = b) of pixel (x, y).
    float& at(int x, int y, int c) { return rgb[index(x, y, c)]; }
    /// Channel c (0 = r, 1 = g, 2 = b) of pixel (x, y).
    float at(int x, int y, int c) const { return rgb[index(x, y, c)]; }
    /// Position of channel c of pixel (x, y) in `rgb`.
    std::size_t index(int x, int y, int c) const {
        return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                    static_cast<std::size_t>(x)) +
               static_cast<std::size_t>(c);
    }
};

/// Loads a PNG (8-bit grey, RGB or RGBA; alpha is ignored) as float RGB in [0, 1]; throws
/// std::runtime_error naming the file when it cannot be read.
Image load_png(const std::filesystem::path& path);
/// load_png on a PNG file's bytes, already read; `source` names them in the message.
Image decode_png(const std::string& bytes, const std::string& source);

/// Writes an image as 8-bit RGB PNG (channels clamped to [0, 1] and rounded); throws
/// std::runtime_error on failure.
void save_png(const std::filesystem::path& path, const Image& image);

/// Largest render side a thresholds or statistics file may state; anything bigger is certainly
/// a typo in a golden test.
inline constexpr int kMaxSide = 16384;

/// How one golden image is rendered and how far a render may stray from it (NAME.txt).
struct Thresholds {
    double rmse = 0.004;          ///< Largest allowed RMSE over all channels of all pixels.
    double pixel_tol = 0.02;      ///< A pixel is an outlier when a channel differs by more.
    double max_fraction = 0.002;  ///< Largest allowed fraction of outlier pixels.
    int width = 192;              ///< Render width in pixels (`size WxH`).
    int height = 144;             ///< Render height in pixels (`size WxH`).
    unsigned seed = 1;            ///< Sampler seed passed to `rt --seed`.
    std::string extra_args;       ///< Extra `rt` arguments (`args ...`, rest of the line).
};

/// Parses a thresholds file of `key value` lines (`size 192x144`, `seed 1`, `rmse 0.004`,
/// `pixel_tol 0.02`, `max_fraction 0.002`, `args --spp 4`; `#` starts a comment). Missing keys
/// keep the defaults above. Throws std::runtime_error "SOURCE:LINE: what is wrong".
Thresholds parse_thresholds(std::istream& in, const std::string& source_name);

/// Reads and parses a thresholds file; throws std::runtime_error naming the file (and line).
Thresholds load_thresholds(const std::filesystem::path& path);

/// The result of comparing a render with its golden image.
struct Comparison {
    double rmse = 0;              ///< Root mean square difference over all channels of all pixels.
    double psnr = 0;              ///< 20 log10(1 / rmse) in dB; +inf for identical images.
    double outlier_fraction = 0;  ///< Fraction of pixels whose largest channel difference > tol.
    double max_diff = 0;          ///< Largest channel difference anywhere.
    bool passed = false;          ///< rmse <= thresholds.rmse and fraction <= max_fraction.
    std::size_t outlier_count = 0;  ///< Number of outlier pixels.
    std::size_t pixel_count = 0;    ///< Number of pixels compared.
    bool size_mismatch = false;     ///< The images differ in size; nothing else was measured.
    std::string reason;  ///< Why it failed when the metric could not run (size mismatch), else "".
};

/// Compares a render with its golden image under the given thresholds.
Comparison compare(const Image& expected, const Image& actual, const Thresholds& thresholds);

/// The verdict in words, e.g. "RMSE 0.0113 > 0.004; 1.9% of pixels beyond 0.02 (allowed 0.2%)"
/// on failure or "RMSE 0.0012 <= 0.004; 0.01% of pixels beyond 0.02, allowed 0.2%" on a pass.
std::string describe(const Comparison& comparison, const Thresholds& thresholds);

/// The difference image: |actual - expected| per channel times `magnify`, clamped to 1, with
/// outlier pixels (largest channel difference > pixel_tol) in pure magenta. When the sizes differ
/// the image covers both, and pixels outside either image are magenta.
Image diff_image(const Image& expected, const Image& actual, double pixel_tol,
                 double magnify = 8.0);

/// Formats v with 3 significant digits, or more when that would print it equal to `limit`
/// although it differs (so "0.00401 > 0.004", never "0.004 > 0.004").
std::string format_against(double v, double limit);

}  // namespace rb::golden
