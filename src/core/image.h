/// \file
/// Image: a float RGB film, and PNG output written atomically.
#pragma once

#include <cstdlib>
#include <functional>
#include <new>
#include <span>
#include <string>
#include <vector>

#include "core/vec.h"

namespace rb {

/// The largest image raybook agrees to render: 2^29 pixels. stb's PNG encoder sizes its buffers
/// with int, so (3w + 1) h bytes must stay below 2^31. Whether an image fits in memory is the
/// memory budget's question (core/memory_budget.h), asked before the render.
inline constexpr long long kMaxPixels = 1LL << 29;
/// The largest width or height.
inline constexpr int kMaxDimension = 1 << 16;

/// Throw InputError unless width × height is a size rt can render and write; `where` prefixes
/// the message.
void checkImageSize(long long width, long long height, const std::string& where);

/// The extension of `path` in lower case, with its dot (".png"), or "" when it has none.
std::string lowerExtension(const std::string& path);
/// True when `path` ends in .png (any case): the format the core writes.
bool hasPngExtension(const std::string& path);
/// Throw InputError (prefixed by `where`) unless `path` ends in .png or in one of `others`
/// (the extensions of the built chapters' formats, e.g. ".hdr"); rt never writes PNG data
/// under another format's name.
void checkOutputName(const std::string& path, const std::string& where,
                     const std::vector<std::string>& others = {});

/// The film's allocator: memory from calloc, which the kernel hands over already zero for a
/// large block, and value-initialisation that writes nothing. A new film then costs no memset:
/// its pages are first touched by the render threads that write them, in parallel, instead of
/// by one thread before the render starts (3.5 ms of page faults for 1024×768 on this machine).
/// Only for a buffer that is sized once and never shrinks and regrows (Image's is private).
template <class T>
struct ZeroedAllocator {
    using value_type = T;
    ZeroedAllocator() = default;
    /// The same allocator for another element type.
    template <class U>
    ZeroedAllocator(const ZeroedAllocator<U>&) {}
    /// n zeroed elements, or std::bad_alloc.
    T* allocate(std::size_t n) {
        if (void* p = std::calloc(n, sizeof(T))) return static_cast<T*>(p);
        throw std::bad_alloc();
    }
    /// Give back a block from allocate.
    void deallocate(T* p, std::size_t) { std::free(p); }
    /// Value-initialise: nothing to write, calloc's memory is already zero.
    template <class U>
    void construct(U*) noexcept {}
    /// Any other construction, as the default allocator does it.
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    /// All ZeroedAllocators are interchangeable.
    friend bool operator==(const ZeroedAllocator&, const ZeroedAllocator&) { return true; }
};

/// A width × height image of linear RGB, row 0 at the top.
class Image {
  public:
    Image(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    /// The colour of pixel (x, y).
    Colour get(int x, int y) const {
        const size_t i = (static_cast<size_t>(y) * width_ + x) * 3;
        return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
    }
    /// Set pixel (x, y).
    void set(int x, int y, const Colour& c) {
        const size_t i = (static_cast<size_t>(y) * width_ + x) * 3;
        rgb_[i] = static_cast<float>(c.r);
        rgb_[i + 1] = static_cast<float>(c.g);
        rgb_[i + 2] = static_cast<float>(c.b);
    }
    /// Raw float RGB data, row-major.
    std::span<const float> data() const { return rgb_; }
    std::span<float> data() { return rgb_; }

  private:
    int width_, height_;
    std::vector<float, ZeroedAllocator<float>> rgb_;  // starts black
};

/// Encode as 8-bit RGB the way the CS488 framework does: clamp each channel to [0,1], then
/// truncate 255·c. Non-finite values become 0.
std::vector<unsigned char> toBytes(const Image& image);

/// Where an encoder sends each piece of a file it writes (stb's stbi_write_func).
using ImageByteSink = void (*)(void* context, void* data, int size);
/// An encoder: streams a whole file into (sink, context); false when it could not allocate.
using ImageEncoder = std::function<bool(ImageByteSink sink, void* context)>;

/// Write a file atomically: `encode` streams it to a temporary file beside `path`, which is
/// then renamed to `path`. Throws InputError naming the path and `format` ("PNG") if it
/// cannot be written (a short write, a full disk, a missing folder), and leaves no partial
/// file behind.
void writeImageFile(const std::string& path, const std::string& format, const ImageEncoder& encode);

/// Write a PNG atomically: to a temporary file beside `path`, then rename. Throws InputError
/// naming the path if it cannot be written, and leaves no partial file behind.
void writePng(const Image& image, const std::string& path);

}  // namespace rb
