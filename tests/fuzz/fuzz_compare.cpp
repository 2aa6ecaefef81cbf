/// \file
/// Fuzz target: rt --compare's image loading (src/app/image_compare.cpp): the bytes decoded
/// by stb_image as load_png decodes a file, then the comparison, its words and the difference
/// picture of the image against itself and against a 4 × 3 image. Bad input must end in
/// std::runtime_error, the error rt --compare reports.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "app/image_compare.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace golden = rb::golden;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const golden::Image image = golden::decode_png(bytes, "fuzz.png");
        const golden::Thresholds thresholds;
        const golden::Image small = golden::Image::filled(4, 3, 0.5f, 0.5f, 0.5f);
        std::string words = golden::describe(golden::compare(image, image, thresholds), thresholds);
        words += golden::describe(golden::compare(small, image, thresholds), thresholds);
        const golden::Image diff = golden::diff_image(small, image, thresholds.pixel_tol);
        // Touch the results so the build cannot optimise the calls away.
        if (words.empty() || diff.rgb.empty()) return 0;
    } catch (const std::runtime_error&) {
        // Bad input, reported as it should be.
    }
    return 0;
}
