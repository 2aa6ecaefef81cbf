#include "core/batch.h"

#include "core/error.h"

namespace rb {

int runBatch(const CommandLine&, int, char**) {
    throw InputError("--batch is not available yet");
}

}  // namespace rb
