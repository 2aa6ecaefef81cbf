/// \file
/// The render identity that fuzz_journal checks journals against, and that make_seeds writes
/// the seed journals for: the fields ./rt puts in a journal's header (src/app/main.cpp).
#pragma once

#include "core/cluster.h"

namespace rbfuzz {

/// The identity of a small render of a chapter scene.
inline rb::RenderIdentity journalIdentity() {
    return {"fuzz.png",
            {{"version", "0.17.0 (fuzz)"},
             {"scene", "fuzz.lua (120 bytes, hash 42)"},
             {"size", "8x8"},
             {"seed", "1"},
             {"sampling", "features all, spp 1, max-depth 5"}}};
}

}  // namespace rbfuzz
