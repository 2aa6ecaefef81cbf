/// \file
/// Fuzz target: the NanoVDB reader of chapter 17's density grids (src/media/vdb_density.cpp):
/// the file's directory, the grid's header, transform, node offsets and values, then the
/// density field it gives, sampled (at) and bounded (maxIn) inside and around its bounds. The
/// grid read is "density", the name the chapter's scenes use. Bad input must end in InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "media/vdb_density.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const auto field = rb::loadVdbDensityBytes(bytes, "fuzz.nvdb", "density", nullptr);
        const rb::AABB box = field->bounds();
        // The corners, centre and a point beyond the bounds; an empty grid's are infinite.
        double sum = field->maxIn(box.lo, box.hi) + field->maxIn(box.lo, 0.5 * (box.lo + box.hi));
        for (int corner = 0; corner < 8; ++corner) {
            sum += field->at(rb::Vec3(corner & 1 ? box.hi.x : box.lo.x,
                                      corner & 2 ? box.hi.y : box.lo.y,
                                      corner & 4 ? box.hi.z : box.lo.z));
        }
        sum += field->at(0.5 * (box.lo + box.hi)) + field->at(box.hi + (box.hi - box.lo));
        // Touch the result so the build cannot optimise the calls away.
        if (sum < 0.0) return 0;
    } catch (const rb::InputError&) {
        // Bad input, reported as it should be.
    }
    return 0;
}
