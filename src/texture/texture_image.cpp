#include "texture/texture_image.h"

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <utility>

#include "core/error.h"

namespace rb {

// [srgb-decode]
double srgbToLinear(double c) {
    // [exercise-srgb]
    // Exercise 10.3, the sRGB decode: read ch10-srgb.
    // Blank: return c;
    // A linear toe near black, then a 2.4 power. Source: IEC 61966-2-1:1999, section 5.2.
    if (c <= 0.04045) return c / 12.92;
    return std::pow((c + 0.055) / 1.055, 2.4);
    // [exercise-srgb]
}
// [srgb-decode]

double linearToSrgb(double linear) {
    // Source: IEC 61966-2-1:1999, section 5.3 (the inverse of srgbToLinear).
    if (linear <= 0.0031308) return 12.92 * linear;
    return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

namespace {

/// A texture coordinate as a continuous texel coordinate in [0, n]: reduced into one period
/// (repeat) or clamped (clamp) first, so that any finite or infinite st stays in range.
double toTexelSpace(double s, int n, Wrap wrap) {
    if (!std::isfinite(s)) s = 0.0;
    s = wrap == Wrap::Repeat ? s - std::floor(s) : std::clamp(s, 0.0, 1.0);
    return s * n;
}

/// A texel index moved into [0, n): wrapped around (repeat) or held at the edge (clamp).
int wrapIndex(int i, int n, Wrap wrap) {
    if (wrap == Wrap::Clamp) return std::clamp(i, 0, n - 1);
    return ((i % n) + n) % n;
}

/// The width and height a PNG's header (its IHDR chunk) claims, read without stb_image: stb
/// refuses images over 1 GiB of pixels without saying that size was the reason.
bool pngHeaderSize(FILE* file, std::uint64_t& width, std::uint64_t& height) {
    unsigned char header[24];
    const bool read = std::fread(header, 1, sizeof header, file) == sizeof header;
    std::rewind(file);
    // Source: the PNG specification (ISO/IEC 15948), 5.2 and 11.2.2: the signature, then the
    // IHDR chunk's length and type, then width and height as big-endian 32-bit numbers.
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (!read || std::memcmp(header, signature, 8) != 0 || std::memcmp(header + 12, "IHDR", 4))
        return false;
    const auto bigEndian = [&](int at) {
        return (std::uint64_t(header[at]) << 24) | (std::uint64_t(header[at + 1]) << 16) |
               (std::uint64_t(header[at + 2]) << 8) | std::uint64_t(header[at + 3]);
    };
    width = bigEndian(16);
    height = bigEndian(20);
    return true;
}

/// Why stb_image could not decode a file whose header it read, in words: its failure reasons
/// are terse codes ("outofdata", "zlib corrupt"), and for a PNG cut off inside a chunk it
/// reports the chunk type it misread ("IDA").
std::string decodeFailure(const std::string& reason) {
    static constexpr std::pair<const char*, const char*> kReasons[] = {
        {"outofdata", "the file ends before its pixel data does"},
        {"read past buffer", "the file ends before its pixel data does"},
        {"not enough pixels", "the file ends before its pixel data does"},
        {"no IDAT", "the file has no pixel data"},
        {"zlib corrupt", "its compressed pixel data is damaged"},
        {"bad zlib header", "its compressed pixel data is damaged"},
        {"bad codelengths", "its compressed pixel data is damaged"},
        {"bad huffman code", "its compressed pixel data is damaged"},
        {"bad code lengths", "its compressed pixel data is damaged"},
        {"bad dist", "its compressed pixel data is damaged"},
        {"invalid filter", "its pixel rows are damaged"},
        {"expected marker", "the JPEG data ends, or is damaged, before its end marker"},
        {"outofmem", "out of memory while decoding"},
    };
    for (const auto& [code, words] : kReasons)
        if (reason == code) return words;
    // A PNG cut off or damaged inside a chunk's header: stb reads a chunk type it does not
    // know and reports it by the bytes it got ("IDA", "", "XyZw PNG chunk not known").
    if (reason.size() < 5 || reason.find("chunk not known") != std::string::npos)
        return "the file ends, or is damaged, inside a PNG chunk";
    return "stb_image: " + reason;
}

}  // namespace

Colour sampleNearest(const TextureImage& image, const Vec2& st, Wrap wrap) {
    const double x = toTexelSpace(st.x, image.width, wrap);
    const double y = toTexelSpace(1.0 - st.y, image.height, wrap);  // v up, rows down
    return image.texel(wrapIndex(static_cast<int>(x), image.width, wrap),
                       wrapIndex(static_cast<int>(y), image.height, wrap));
}

// [bilinear]
Colour sampleBilinear(const TextureImage& image, const Vec2& st, Wrap wrap) {
    // [exercise-bilinear]
    // Exercise 10.4, bilinear filtering: read ch10-bilinear.
    // Blank: return sampleNearest(image, st, wrap);
    // Continuous texel coordinates with texel centres at whole numbers.
    const double x = toTexelSpace(st.x, image.width, wrap) - 0.5;
    const double y = toTexelSpace(1.0 - st.y, image.height, wrap) - 0.5;  // v up, rows down
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    // The four texels around (x, y), each index wrapped or clamped.
    const int i0 = wrapIndex(static_cast<int>(x0), image.width, wrap);
    const int i1 = wrapIndex(static_cast<int>(x0) + 1, image.width, wrap);
    const int j0 = wrapIndex(static_cast<int>(y0), image.height, wrap);
    const int j1 = wrapIndex(static_cast<int>(y0) + 1, image.height, wrap);
    // Blend along x on both rows, then along y.
    const Colour top = (1.0 - fx) * image.texel(i0, j0) + fx * image.texel(i1, j0);
    const Colour bottom = (1.0 - fx) * image.texel(i0, j1) + fx * image.texel(i1, j1);
    return (1.0 - fy) * top + fy * bottom;
    // [exercise-bilinear]
}
// [bilinear]

std::uint64_t textureImageBytes(std::uint64_t width, std::uint64_t height, bool hdr) {
    return saturatingProduct(saturatingProduct(width, height), hdr ? 12 + 12 : 16);
}

std::shared_ptr<const TextureImage> loadTextureImage(const std::string& path,
                                                     const MemoryBudget& budget) {
    // A folder opens like a file on Linux, and then reads as nothing: say what it is.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(path + ": is a directory, not an image file");
    // Read the header first: an absurd size is refused before anything is decoded.
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) throw InputError(path + ": cannot open the texture image");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_file(file.get(), &width, &height, &channels)) {
        std::uint64_t w = 0, h = 0;
        if (pngHeaderSize(file.get(), w, h)) {
            if (w == 0 || h == 0)
                throw InputError(path + ": the image is empty (" + std::to_string(w) + "x" +
                                 std::to_string(h) + ")");
            budget.require(textureImageBytes(w, h), path,
                           "the " + std::to_string(w) + "x" + std::to_string(h) + " texture image");
            throw InputError(path + ": the PNG's header is damaged, or its " + std::to_string(w) +
                             "x" + std::to_string(h) + " pixels are more than stb_image decodes (" +
                             stbi_failure_reason() + ")");
        }
        throw InputError(path + ": not an image stb_image can read (" + stbi_failure_reason() +
                         "); expected PNG, JPEG, BMP, TGA, GIF, PSD, PIC, PNM or HDR");
    }
    if (width <= 0 || height <= 0)
        throw InputError(path + ": the image is empty (" + std::to_string(width) + "x" +
                         std::to_string(height) + ")");
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const bool hdr = stbi_is_hdr_from_file(file.get()) != 0;
    budget.require(textureImageBytes(width, height, hdr), path, "the " + size + " texture image");
    // Decode to RGB: floats for a Radiance .hdr (already linear), else 8 bits (sRGB).
    auto image = std::make_shared<TextureImage>();
    image->width = width;
    image->height = height;
    image->name = path;
    const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
    int w = 0, h = 0, n = 0;
    if (hdr) {
        std::unique_ptr<float, void (*)(void*)> pixels(
            stbi_loadf_from_file(file.get(), &w, &h, &n, 3), stbi_image_free);
        if (!pixels || w != width || h != height)
            throw InputError(path + ": the image is truncated or corrupt (" +
                             decodeFailure(stbi_failure_reason()) + ")");
        image->texels.resize(count);
        for (size_t k = 0; k < count; ++k) {
            const float* p = pixels.get() + 3 * k;
            // A negative or non-finite texel would put NaN into the render.
            for (int c = 0; c < 3; ++c)
                image->texels[k][c] = std::isfinite(p[c]) ? std::max(p[c], 0.0f) : 0.0f;
        }
        return image;
    }
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_file(file.get(), &w, &h, &n, 3),
                                                     stbi_image_free);
    if (!pixels || w != width || h != height)
        throw InputError(path + ": the image is truncated or corrupt (" +
                         decodeFailure(stbi_failure_reason()) + ")");
    // Keep stb's sRGB bytes as they are, and decode each of the 256 levels once.
    for (int k = 0; k < 256; ++k)
        image->srgbToLinearTable[k] = static_cast<float>(srgbToLinear(k / 255.0));
    image->srgb = std::shared_ptr<const std::uint8_t>(pixels.release(), stbi_image_free);
    return image;
}

}  // namespace rb
