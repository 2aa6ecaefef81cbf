#include "core/image.h"

#include <stb_image_write.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.h"

namespace rb {

void checkImageSize(long long width, long long height, const std::string& where) {
    if (width <= 0 || height <= 0)
        throw InputError(where + "image size " + std::to_string(width) + "x" +
                         std::to_string(height) + " is not positive");
    if (width > kMaxDimension || height > kMaxDimension || width * height > kMaxPixels)
        throw InputError(where + "image size " + std::to_string(width) + "x" +
                         std::to_string(height) + " is too large (at most " +
                         std::to_string(kMaxDimension) + " per side and " +
                         std::to_string(kMaxPixels) + " pixels)");
}

bool hasPngExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png";
}

void checkOutputName(const std::string& path, const std::string& where) {
    if (!hasPngExtension(path))
        throw InputError(where + ": cannot write '" + path +
                         "': rt writes PNG images only, so the name must end in .png");
}

Image::Image(int width, int height) : width_(width), height_(height) {
    checkImageSize(width, height, "");
    rgb_.assign(static_cast<size_t>(width) * height * 3, 0.0f);
}

Colour Image::get(int x, int y) const {
    const size_t i = (static_cast<size_t>(y) * width_ + x) * 3;
    return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

void Image::set(int x, int y, const Colour& c) {
    const size_t i = (static_cast<size_t>(y) * width_ + x) * 3;
    rgb_[i] = static_cast<float>(c.r);
    rgb_[i + 1] = static_cast<float>(c.g);
    rgb_[i + 2] = static_cast<float>(c.b);
}

std::vector<unsigned char> toBytes(const Image& image) {
    std::vector<unsigned char> bytes(image.data().size());
    for (size_t i = 0; i < bytes.size(); ++i) {
        float c = image.data()[i];
        if (!std::isfinite(c)) c = 0.0f;
        c = std::clamp(c, 0.0f, 1.0f);
        bytes[i] = static_cast<unsigned char>(255.0f * c);  // truncation, as the course does
    }
    return bytes;
}

// [write-png]
namespace {

/// Where stb's encoder hands over the PNG: a file, and the first write error (errno).
struct PngSink {
    std::FILE* file;
    int error = 0;
};

/// stb's write callback: fwrite, remembering a short write (stbi_write_png itself ignores
/// them, and would leave a truncated file behind on a full disk).
void writeToSink(void* context, void* data, int size) {
    auto* sink = static_cast<PngSink*>(context);
    if (sink->error == 0 &&
        std::fwrite(data, 1, static_cast<size_t>(size), sink->file) != static_cast<size_t>(size))
        sink->error = errno ? errno : EIO;
}

/// Encode `image` into the new file `path`; returns 0 or the errno of the first failure.
int writePngFile(const Image& image, const std::string& path) {
    const std::vector<unsigned char> bytes = toBytes(image);
    errno = 0;
    PngSink sink{std::fopen(path.c_str(), "wb")};
    if (!sink.file) return errno ? errno : EIO;
    const int ok = stbi_write_png_to_func(writeToSink, &sink, image.width(), image.height(), 3,
                                          bytes.data(), image.width() * 3);
    // The last bytes reach the disk only at fflush and fclose: check both.
    if (sink.error == 0 && std::fflush(sink.file) != 0) sink.error = errno ? errno : EIO;
    if (std::fclose(sink.file) != 0 && sink.error == 0) sink.error = errno ? errno : EIO;
    if (!ok && sink.error == 0) sink.error = ENOMEM;  // the encoder could not allocate
    return sink.error;
}

}  // namespace

void writePng(const Image& image, const std::string& path) {
    // Write to a temporary name in the same folder, so the rename below is atomic.
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    int error = writePngFile(image, tmp);
    if (error == 0 && std::rename(tmp.c_str(), path.c_str()) != 0) error = errno;
    if (error != 0) {
        std::remove(tmp.c_str());
        throw InputError(path + ": cannot write the PNG file (" + std::strerror(error) + ")");
    }
}
// [write-png]

}  // namespace rb
