/// \file
/// Texture images: texels decoded once to linear RGB, looked up with wrap or clamp at the
/// edges and filtered bilinearly; the sRGB decode of 8-bit files; loading with stb_image.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/memory_budget.h"
#include "core/vec.h"

namespace rb {

/// What happens outside [0, 1]: the image repeats (tiles), or its edge texels extend.
enum class Wrap { Repeat, Clamp };

/// An image as textures read it: linear RGB texels, row 0 at the top (as files store it).
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> texels;  ///< width × height, row by row; floats halve the memory.
    std::string name;               ///< The file it came from, for messages.

    /// The texel in column x and row y (0 ≤ x < width, 0 ≤ y < height).
    Colour texel(int x, int y) const {
        return Colour(texels[static_cast<size_t>(y) * static_cast<size_t>(width) + x]);
    }
};

/// The linear value of an sRGB-encoded value c in [0, 1] (IEC 61966-2-1).
double srgbToLinear(double c);
/// The sRGB encoding of a linear value in [0, 1]: the inverse of srgbToLinear.
double linearToSrgb(double linear);

/// The texel nearest to texture coordinate st (v up: v = 0 is the image's bottom row).
Colour sampleNearest(const TextureImage& image, const Vec2& st, Wrap wrap);

/// The bilinear blend of the four texels around st: texel (x, y) holds the value at its
/// centre ((x + ½)/w, 1 − (y + ½)/h), and between centres the value is linear along each axis.
Colour sampleBilinear(const TextureImage& image, const Vec2& st, Wrap wrap);

/// Bytes that loading a width × height image takes at its peak: stb's decoded pixels (up to
/// 12 per pixel, for a float .hdr; for a PNG its inflated rows and the pixels) and the linear
/// texels (12). An estimate from stb_image's buffers, not a measurement.
std::uint64_t textureImageBytes(std::uint64_t width, std::uint64_t height);

/// Load an image file that stb_image reads (PNG, JPEG, BMP, TGA, GIF, PSD, PIC, PNM, HDR).
/// 8-bit channels are sRGB-decoded to linear, a Radiance .hdr is already linear; grey and
/// grey-alpha images become RGB and alpha is dropped. Throws InputError naming the file when it
/// is missing, truncated, corrupt, empty, or too large for `budget`.
std::shared_ptr<const TextureImage> loadTextureImage(const std::string& path,
                                                     const MemoryBudget& budget = {});

}  // namespace rb
