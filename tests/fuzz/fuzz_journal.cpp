/// \file
/// Fuzz target: the tile journal reader that --resume runs (src/mpi/journal.cpp): the header
/// checked against the render's identity, then the tile records up to the first torn one. The
/// identity is fixed here; the seed journals were written for it (tests/fuzz/make_seeds.cpp).
/// Bad input must end in InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "mpi/journal.h"
#include "seed_identity.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const auto tiles =
            rb::readJournalBytes(bytes, "fuzz.png.journal", rbfuzz::journalIdentity());
        // Touch the result so the build cannot optimise the call away.
        if (tiles.empty()) return 0;
    } catch (const rb::InputError&) {
        // Bad input, reported as it should be.
    }
    return 0;
}
