#include "core/memory_budget.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "core/from_chars.h"

namespace rb {
namespace {

constexpr std::uint64_t kMiB = std::uint64_t(1) << 20;

/// The number in a cgroup limit file ("max" or unreadable: no limit).
std::uint64_t cgroupLimit(const char* path) {
    std::ifstream in(path);
    std::string text;
    if (!(in >> text) || text == "max") return std::numeric_limits<std::uint64_t>::max();
    std::uint64_t value = 0;
    const auto [end, ec] = rb::fromChars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        return std::numeric_limits<std::uint64_t>::max();
    return value;
}

/// Physical memory, or the container's limit when smaller.
std::uint64_t machineMemory() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGE_SIZE);
    std::uint64_t bytes = pages > 0 && pageSize > 0
                              ? saturatingProduct(static_cast<std::uint64_t>(pages),
                                                  static_cast<std::uint64_t>(pageSize))
                              : std::uint64_t(4) << 30;  // cannot tell: assume a small machine
    // cgroup v2, then v1 (v1 reports "no limit" as a huge number, which min() ignores).
    bytes = std::min(bytes, cgroupLimit("/sys/fs/cgroup/memory.max"));
    bytes = std::min(bytes, cgroupLimit("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
    return bytes;
}

/// The multiplier of a size suffix ("", "K", "KiB", "KB", ... any case), or 0 if unknown.
std::uint64_t suffixMultiplier(std::string suffix) {
    for (char& c : suffix) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (suffix.empty() || suffix == "B") return 1;
    static const char* const kUnits = "KMGT";
    for (int i = 0; i < 4; ++i) {
        const std::string u(1, kUnits[i]);
        if (suffix == u || suffix == u + "B" || suffix == u + "IB")
            return std::uint64_t(1) << (10 * (i + 1));
    }
    return 0;
}

}  // namespace

std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b) {
    if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
        return std::numeric_limits<std::uint64_t>::max();
    return a * b;
}

std::uint64_t residentBytes() {
    // /proc/self/statm: total program size, then resident pages.
    std::ifstream statm("/proc/self/statm");
    std::uint64_t size = 0, resident = 0;
    if (!(statm >> size >> resident)) return 0;
    return resident * static_cast<std::uint64_t>(sysconf(_SC_PAGE_SIZE));
}

std::string formatBytes(std::uint64_t bytes) {
    if (bytes == std::numeric_limits<std::uint64_t>::max()) return "more than 16 EiB";
    static const char* const kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1024.0 && unit < 6) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    if (unit == 0 || value >= 100.0)
        std::snprintf(text, sizeof text, "%.0f %s", value, kUnits[unit]);
    else
        std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
    return text;
}

std::uint64_t MemoryBudget::available() const {
    const std::uint64_t held = residentBytes();
    return held >= limit ? 0 : limit - held;
}

std::string MemoryBudget::refusal(std::uint64_t bytes, std::uint64_t free, const std::string& where,
                                  const std::string& what) const {
    return where + ": " + what + " needs about " + formatBytes(bytes) + ", but only " +
           formatBytes(free) + " of the memory limit of " + formatBytes(limit) + " (" + origin +
           ") is free; raise it with --max-memory SIZE if the machine has the memory";
}

void MemoryBudget::require(std::uint64_t bytes, const std::string& where,
                           const std::string& what) const {
    const std::uint64_t free = available();
    if (bytes > free) throw InputError(refusal(bytes, free, where, what));
}

MemoryBudget defaultMemoryBudget() {
    const std::uint64_t machine = machineMemory();
    MemoryBudget budget;
    budget.limit = machine / 2;
#ifdef __EMSCRIPTEN__
    // In the docs' live panels (src/web) the "machine" is the page's WebAssembly memory.
    budget.origin = "the default: half of the " + formatBytes(machine) +
                    " this page's WebAssembly can use";
#else
    budget.origin = "the default: half of this machine's " + formatBytes(machine);
#endif
    return budget;
}

MemoryBudget memoryBudgetFromOption(const std::string& size) {
    const auto fail = [&] {
        return InputError(
            "--max-memory: expected a size of at least 1M, such as 512M or 4G "
            "(K, M, G and T are powers of 1024), got '" +
            size + "'");
    };
    double number = 0.0;
    const char* first = size.data();
    const char* last = size.data() + size.size();
    const auto [end, ec] = rb::fromChars(first, last, number);
    if (ec != std::errc() || end == first || !std::isfinite(number) || number < 0) throw fail();
    const std::uint64_t multiplier = suffixMultiplier(std::string(end, last));
    if (multiplier == 0) throw fail();
    const double bytes = number * static_cast<double>(multiplier);
    if (bytes < static_cast<double>(kMiB)) throw fail();
    MemoryBudget budget;
    // Anything past 2^63 bytes is no limit in practice.
    budget.limit = bytes >= 9.2e18 ? std::numeric_limits<std::uint64_t>::max()
                                   : static_cast<std::uint64_t>(bytes);
    budget.origin = "--max-memory " + size;
    return budget;
}

}  // namespace rb
