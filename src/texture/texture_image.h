/// \file
/// Texture images: texels decoded once to linear RGB, looked up with wrap or clamp at the
/// edges and filtered bilinearly; the sRGB decode of 8-bit files; loading with stb_image.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/memory_budget.h"
#include "core/vec.h"

namespace rb {

/// What happens outside [0, 1]: the image repeats (tiles), or its edge texels extend.
enum class Wrap { Repeat, Clamp };

/// An image as textures read it: linear RGB texels, row 0 at the top (as files store it).
/// An 8-bit file keeps its sRGB bytes, 3 per texel, decoded by a table at each lookup (an
/// 8192² image takes 192 MiB, not the 768 MiB of float texels); a Radiance .hdr, or an image
/// built in memory, keeps linear float texels.
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> texels;  ///< width × height linear texels, row by row, when not srgb.
    /// width × height × 3 sRGB bytes, row by row (stb_image's own buffer), or null.
    std::shared_ptr<const std::uint8_t> srgb;
    std::array<float, 256> srgbToLinearTable{};  ///< The linear value of each sRGB byte.
    std::string name;                            ///< The file it came from, for messages.

    /// The linear texel in column x and row y (0 ≤ x < width, 0 ≤ y < height).
    Colour texel(int x, int y) const {
        const size_t k = static_cast<size_t>(y) * static_cast<size_t>(width) + x;
        if (srgb) {
            const std::uint8_t* p = srgb.get() + 3 * k;
            return Colour(srgbToLinearTable[p[0]], srgbToLinearTable[p[1]],
                          srgbToLinearTable[p[2]]);
        }
        return Colour(texels[k]);
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

/// Bytes that loading a width × height image takes at its peak, an upper bound from
/// stb_image's buffers. An 8-bit file: 16 per pixel (a 16-bit RGBA PNG's inflated rows, 8, and
/// its pixels converted to 3 channels, then to the 3 bytes kept; an 8-bit RGB PNG measured 6).
/// A float .hdr: 24 (stb's 12 per pixel, and the linear float texels kept, 12).
std::uint64_t textureImageBytes(std::uint64_t width, std::uint64_t height, bool hdr = false);

/// Load an image file that stb_image reads (PNG, JPEG, BMP, TGA, GIF, PSD, PIC, PNM, HDR).
/// 8-bit channels are sRGB-decoded to linear, a Radiance .hdr is already linear; grey and
/// grey-alpha images become RGB and alpha is dropped. Throws InputError naming the file when it
/// is missing, truncated, corrupt, empty, or too large for `budget`.
std::shared_ptr<const TextureImage> loadTextureImage(const std::string& path,
                                                     const MemoryBudget& budget = {});

}  // namespace rb
