#include "core/single_process.h"

#include <stdexcept>

#include "core/error.h"
#include "core/interrupt.h"

namespace rb {

int exitCodeOf(std::exception_ptr failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const RenderStopped& e) {
        return e.exitCode;
    } catch (const AgreedFailure& e) {
        return e.exitCode;
    } catch (...) {
        return 1;
    }
}

void SingleProcess::agree(std::exception_ptr failure) {
    if (failure) throw AgreedFailure{exitCodeOf(failure), failure};
}

void SingleProcess::renderTiles(const TileWork&, Image&, RayCounters&) {
    throw std::logic_error("SingleProcess::renderTiles: one process renders with render()");
}

std::vector<std::byte> SingleProcess::joinInOrder(std::span<const std::byte> mine) {
    return {mine.begin(), mine.end()};
}

std::vector<std::vector<std::byte>> SingleProcess::gatherToFirst(std::span<const std::byte> mine) {
    return {{mine.begin(), mine.end()}};
}

}  // namespace rb
