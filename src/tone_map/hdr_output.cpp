#include "tone_map/hdr_output.h"

#include <stb_image_write.h>

#include <cmath>
#include <vector>

namespace rb {

// [write-hdr]
void writeHdr(const Image& film, const std::string& path) {
    // RGBE shares one exponent between the three channels and has no sign: a negative or
    // non-finite value would come out as garbage, so it is stored as 0.
    std::vector<float> rgb(film.data().begin(), film.data().end());
    for (float& c : rgb)
        if (!std::isfinite(c) || c < 0.0f) c = 0.0f;
    writeImageFile(path, "Radiance HDR", [&](ImageByteSink sink, void* context) {
        return stbi_write_hdr_to_func(sink, context, film.width(), film.height(), 3, rgb.data()) !=
               0;
    });
}
// [write-hdr]

}  // namespace rb
