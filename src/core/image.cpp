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

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool hasPngExtension(const std::string& path) {
    return lowerExtension(path) == ".png";
}

void checkOutputName(const std::string& path, const std::string& where,
                     const std::vector<std::string>& others) {
    if (hasPngExtension(path)) return;
    const std::string ext = lowerExtension(path);
    std::string names = ".png";
    for (const std::string& other : others) {
        if (ext == other) return;
        names += " or " + other;
    }
    throw InputError(where + ": cannot write '" + path + "': rt writes " +
                     (others.empty() ? "PNG images only" : "only these formats") +
                     ", so the name must end in " + names);
}

Image::Image(int width, int height) : width_(width), height_(height) {
    checkImageSize(width, height, "");
    rgb_.resize(static_cast<size_t>(width) * height * 3);  // zero, see ZeroedAllocator
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

/// Where an encoder hands over the file: a file, and the first write error (errno).
struct FileSink {
    std::FILE* file;
    int error = 0;
};

/// stb's write callback: fwrite, remembering a short write (stb's encoders themselves ignore
/// them, and would leave a truncated file behind on a full disk).
void writeToSink(void* context, void* data, int size) {
    auto* sink = static_cast<FileSink*>(context);
    if (sink->error == 0 &&
        std::fwrite(data, 1, static_cast<size_t>(size), sink->file) != static_cast<size_t>(size))
        sink->error = errno ? errno : EIO;
}

/// Encode into the new file `path`; returns 0 or the errno of the first failure.
int encodeToFile(const std::string& path, const ImageEncoder& encode) {
    errno = 0;
    FileSink sink{std::fopen(path.c_str(), "wb")};
    if (!sink.file) return errno ? errno : EIO;
    const bool ok = encode(writeToSink, &sink);
    // The last bytes reach the disk only at fflush and fclose: check both.
    if (sink.error == 0 && std::fflush(sink.file) != 0) sink.error = errno ? errno : EIO;
    if (std::fclose(sink.file) != 0 && sink.error == 0) sink.error = errno ? errno : EIO;
    if (!ok && sink.error == 0) sink.error = ENOMEM;  // the encoder could not allocate
    return sink.error;
}

}  // namespace

void writeImageFile(const std::string& path, const std::string& format,
                    const ImageEncoder& encode) {
    // Write to a temporary name in the same folder, so the rename below is atomic.
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    int error = encodeToFile(tmp, encode);
    if (error == 0 && std::rename(tmp.c_str(), path.c_str()) != 0) error = errno;
    if (error != 0) {
        std::remove(tmp.c_str());
        throw InputError(path + ": cannot write the " + format + " file (" + std::strerror(error) +
                         ")");
    }
}

void writePng(const Image& image, const std::string& path) {
    const std::vector<unsigned char> bytes = toBytes(image);
    writeImageFile(path, "PNG", [&](ImageByteSink sink, void* context) {
        return stbi_write_png_to_func(sink, context, image.width(), image.height(), 3, bytes.data(),
                                      image.width() * 3) != 0;
    });
}
// [write-png]

}  // namespace rb
