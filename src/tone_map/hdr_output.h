/// \file
/// Radiance HDR output: the film's linear radiance, unclamped, as an RGBE .hdr file.
#pragma once

#include <string>

#include "core/image.h"

namespace rb {

/// Write the film to `path` as a Radiance .hdr (RGBE) image, atomically. Negative and
/// non-finite values, which RGBE cannot store, are written as 0. Throws InputError naming the
/// path if it cannot be written, and leaves no partial file behind.
void writeHdr(const Image& film, const std::string& path);

}  // namespace rb
