#include "mpi/journal.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/error.h"

namespace rb {
namespace {

constexpr char kJournalMagic[] = "raybook tile journal 1\n";
constexpr char kTileMagic[4] = {'T', 'I', 'L', 'E'};

/// The header: the magic line, one "name=value" line per identity field, an empty line.
std::string headerOf(const RenderIdentity& identity) {
    std::string header = kJournalMagic;
    for (const auto& [name, value] : identity.fields) header += name + "=" + value + "\n";
    return header + "\n";
}

/// The checksum of one record: its position, count and floats.
std::uint64_t recordChecksum(std::int32_t position, std::uint32_t count, const float* pixels) {
    std::uint64_t h = fnv1a64({reinterpret_cast<const unsigned char*>(&position), 4});
    h = fnv1a64({reinterpret_cast<const unsigned char*>(&count), 4}, h);
    return fnv1a64({reinterpret_cast<const unsigned char*>(pixels), count * sizeof(float)}, h);
}

/// Write `size` bytes or throw.
void writeAll(std::FILE* file, const void* data, std::size_t size, const std::string& path) {
    if (std::fwrite(data, 1, size, file) != size)
        throw InputError("cannot write the journal " + path + ": " + std::strerror(errno));
}

/// Append one record to `file` and flush it.
void writeRecord(std::FILE* file, int position, std::span<const float> pixels,
                 const std::string& path) {
    const std::int32_t pos = position;
    const std::uint32_t count = static_cast<std::uint32_t>(pixels.size());
    const std::uint64_t sum = recordChecksum(pos, count, pixels.data());
    writeAll(file, kTileMagic, 4, path);
    writeAll(file, &pos, 4, path);
    writeAll(file, &count, 4, path);
    writeAll(file, pixels.data(), pixels.size_bytes(), path);
    writeAll(file, &sum, 8, path);
}

}  // namespace

std::uint64_t fnv1a64(std::span<const unsigned char> bytes, std::uint64_t hash) {
    for (unsigned char b : bytes) hash = (hash ^ b) * 0x100000001b3ULL;
    return hash;
}

std::string journalPath(const std::string& output) {
    return output + ".journal";
}

JournalWriter::JournalWriter(const std::string& path, const RenderIdentity& identity,
                             const std::vector<JournalTile>& tiles)
    : path_(path) {
    // Write the header and the tiles kept under a temporary name, then rename over the old
    // journal, so a kill now leaves the old journal or the new one, never half of either.
    const std::string tmp = path + ".tmp";
    std::FILE* file = std::fopen(tmp.c_str(), "wb");
    if (!file) throw InputError("cannot write the journal " + tmp + ": " + std::strerror(errno));
    try {
        const std::string header = headerOf(identity);
        writeAll(file, header.data(), header.size(), tmp);
        for (const JournalTile& t : tiles) writeRecord(file, t.position, t.pixels, tmp);
        if (std::fflush(file) != 0)
            throw InputError("cannot write the journal " + tmp + ": " + std::strerror(errno));
    } catch (...) {
        std::fclose(file);
        std::remove(tmp.c_str());
        throw;
    }
    std::fclose(file);
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
        throw InputError("cannot write the journal " + path + ": " + std::strerror(errno));
    file_ = std::fopen(path.c_str(), "ab");
    if (!file_) throw InputError("cannot write the journal " + path + ": " + std::strerror(errno));
}

JournalWriter::~JournalWriter() {
    if (file_) std::fclose(file_);
}

void JournalWriter::append(int position, std::span<const float> pixels) {
    writeRecord(file_, position, pixels, path_);
    // fflush hands the record to the kernel: a SIGKILL after it loses nothing.
    if (std::fflush(file_) != 0)
        throw InputError("cannot write the journal " + path_ + ": " + std::strerror(errno));
}

void JournalWriter::discard() {
    if (file_) std::fclose(file_);
    file_ = nullptr;
    std::remove(path_.c_str());
}

std::vector<JournalTile> readJournal(const std::string& path, const RenderIdentity& identity) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("--resume: cannot read the journal " + path);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return readJournalBytes(bytes, path, identity);
}

std::vector<JournalTile> readJournalBytes(const std::string& bytes, const std::string& path,
                                          const RenderIdentity& identity) {
    // Step 1: the header must be a journal's, written for this render.
    const std::string expected = headerOf(identity);
    if (bytes.rfind(kJournalMagic, 0) != 0)
        throw InputError("--resume: " + path + " is not a raybook tile journal");
    const std::size_t end = bytes.find("\n\n");
    if (end == std::string::npos)
        throw InputError("--resume: " + path + " is not a raybook tile journal (no header end)");
    std::istringstream header(
        bytes.substr(sizeof kJournalMagic - 1, end + 1 - (sizeof kJournalMagic - 1)));
    std::string line;
    for (const auto& [name, value] : identity.fields) {
        std::string found = "(missing)";
        if (std::getline(header, line) && line.rfind(name + "=", 0) == 0)
            found = line.substr(name.size() + 1);
        // A file the scene reads: say which, and that it changed.
        if (found != value && name.rfind("file ", 0) == 0) {
            const std::string file = name.substr(5);
            throw InputError("--resume: " +
                             (found == "(missing)"
                                  ? file + " was not read by the render that wrote " + path
                                  : file + " changed since the journal " + path + " was written (" +
                                        found + "; now " + value + ")") +
                             "; render without --resume to start again");
        }
        if (found != value)
            throw InputError(
                "--resume: the journal " + path + " was written for another render: " + name + " " +
                found + ", this render has " + value + "; render without --resume to start again");
    }
    if (bytes.compare(0, end + 2, expected) != 0)
        throw InputError("--resume: the journal " + path +
                         " was written for another render (its header differs)");
    // Step 2: the records, up to the first one cut short or damaged.
    std::vector<JournalTile> tiles;
    std::size_t at = end + 2;
    while (bytes.size() - at >= 12 && std::memcmp(bytes.data() + at, kTileMagic, 4) == 0) {
        std::int32_t position = 0;
        std::uint32_t count = 0;
        std::memcpy(&position, bytes.data() + at + 4, 4);
        std::memcpy(&count, bytes.data() + at + 8, 4);
        const std::size_t size = 12 + std::size_t{count} * sizeof(float) + 8;
        if (bytes.size() - at < size) break;
        JournalTile tile{position, std::vector<float>(count)};
        // An empty vector's data() may be null, which memcpy must not get even for 0 bytes.
        if (count > 0)
            std::memcpy(tile.pixels.data(), bytes.data() + at + 12, count * sizeof(float));
        std::uint64_t sum = 0;
        std::memcpy(&sum, bytes.data() + at + size - 8, 8);
        if (sum != recordChecksum(position, count, tile.pixels.data())) break;
        tiles.push_back(std::move(tile));
        at += size;
    }
    return tiles;
}

}  // namespace rb
