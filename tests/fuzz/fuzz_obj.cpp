/// \file
/// Fuzz target: the OBJ reader (src/bvh/obj.cpp), then the mesh and its BVH (src/bvh/mesh.cpp,
/// bvh.cpp) from whatever it accepted. Bad input must end in InputError; anything else (a
/// crash, a sanitizer report, another exception, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "bvh/mesh.h"
#include "bvh/obj.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const rb::ObjData obj = rb::parseObj(in, "fuzz.obj");
        const rb::Mesh mesh(obj, "fuzz.obj");
        // Touch the result so the build cannot be optimised away.
        if (mesh.triangleCount() + mesh.droppedCount() == 0) return 0;
    } catch (const rb::InputError&) {
        // Bad input, reported as it should be.
    }
    return 0;
}
