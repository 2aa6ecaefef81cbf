/// \file
/// The tile journal: a sidecar file beside an image that holds its finished tiles as they
/// arrive, so that a render killed halfway finishes later from where it stopped (--resume).
#pragma once

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "core/cluster.h"

namespace rb {

/// One finished tile: its position in render order and its film's pixels, RGB floats.
struct JournalTile {
    int position = 0;
    std::vector<float> pixels;
};

/// The 64-bit FNV-1a hash of `bytes` (Fowler, Noll and Vo), continuing from `hash`.
std::uint64_t fnv1a64(std::span<const unsigned char> bytes,
                      std::uint64_t hash = 0xcbf29ce484222325ULL);

/// Where the journal of the image `output` is kept: "out.png" -> "out.png.journal".
std::string journalPath(const std::string& output);

/// Appends finished tiles to a journal. The file starts with a text header (the render's
/// identity), then one record per tile: "TILE", the position, the float count, the floats and
/// an FNV-1a checksum, so a record cut short by a kill is recognised and dropped.
class JournalWriter {
  public:
    /// Start the journal at `path` for `identity`, holding `tiles` already (those a resumed
    /// render read back; a torn last record is left behind). Replaces the file atomically.
    JournalWriter(const std::string& path, const RenderIdentity& identity,
                  const std::vector<JournalTile>& tiles = {});
    ~JournalWriter();
    JournalWriter(const JournalWriter&) = delete;
    JournalWriter& operator=(const JournalWriter&) = delete;

    /// Append one tile and hand it to the operating system, so a killed rt keeps it.
    void append(int position, std::span<const float> pixels);
    /// Close and delete the journal: the image is written.
    void discard();

  private:
    std::string path_;
    std::FILE* file_ = nullptr;
};

/// The tiles of the journal at `path`, in the order written, after checking that it was
/// written for `identity`; a torn last record is dropped. Throws InputError for a file that is
/// no journal, or one written for another render (naming what differs).
std::vector<JournalTile> readJournal(const std::string& path, const RenderIdentity& identity);

/// readJournal on the journal's bytes, already read; `path` names it in messages.
std::vector<JournalTile> readJournalBytes(const std::string& bytes, const std::string& path,
                                          const RenderIdentity& identity);

}  // namespace rb
