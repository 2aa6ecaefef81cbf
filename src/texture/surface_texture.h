/// \file
/// Surface textures: a function of texture coordinates (s, t), placed on a surface by a UV
/// mapping and a tiling; the image texture and the procedural checker are the two kinds.
#pragma once

#include <memory>

#include "core/texture.h"
#include "texture/texture_image.h"
#include "texture/uv_mapping.h"

namespace rb {

/// A texture defined over texture coordinates (s, t) = uv · scale + offset, where uv comes from
/// the surface by `mapping`. Scale tiles the texture: {4, 4} repeats it four times each way.
class SurfaceTexture : public Texture {
  public:
    UVMapping mapping = UVMapping::Surface;  ///< Where (u, v) comes from.
    Vec2 scale{1.0};                         ///< Repeats across one unit of (u, v).
    Vec2 offset{0.0};                        ///< Shift, in texture coordinates.

    /// The colour at a surface point: lookup() at the point's texture coordinates.
    Colour evaluate(const Hit& hit) const final { return lookup(textureCoordinates(hit)); }
    /// The point's texture coordinates (s, t).
    Vec2 textureCoordinates(const Hit& hit) const {
        return surfaceUV(hit, mapping).uv * scale + offset;
    }
    /// The colour at texture coordinates st (linear RGB).
    virtual Colour lookup(const Vec2& st) const = 0;
};

/// An image on the surface, filtered bilinearly (or nearest, to show the texels).
class ImageTexture final : public SurfaceTexture {
  public:
    explicit ImageTexture(std::shared_ptr<const TextureImage> image) : image_(std::move(image)) {}
    Wrap wrap = Wrap::Repeat;  ///< Outside [0, 1]: tile, or extend the edge.
    bool bilinear = true;      ///< False: the nearest texel.
    /// The filtered image at st.
    Colour lookup(const Vec2& st) const override {
        return bilinear ? sampleBilinear(*image_, st, wrap) : sampleNearest(*image_, st, wrap);
    }
    /// The image, shared with every texture made from the same file.
    const TextureImage& image() const { return *image_; }

  private:
    std::shared_ptr<const TextureImage> image_;
};

/// The procedural checker: unit squares of texture space in two colours, `even` where
/// ⌊s⌋ + ⌊t⌋ is even and `odd` elsewhere (scale {8, 8} gives 8 × 8 squares over a face).
class CheckerTexture final : public SurfaceTexture {
  public:
    CheckerTexture(const Colour& even, const Colour& odd) : even_(even), odd_(odd) {}
    /// The square's colour at st.
    Colour lookup(const Vec2& st) const override;

  private:
    Colour even_, odd_;
};

}  // namespace rb
