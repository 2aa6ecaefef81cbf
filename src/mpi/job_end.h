/// \file
/// What a rank says when mpirun ends the job: a rank died (Open MPI 4.1 then sends SIGTERM to
/// the others, and SIGKILL a second later), or the user pressed Ctrl-C or sent SIGTERM to
/// mpirun (the same SIGTERM to every rank). Pure logic: src/mpi/mpi_cluster.cpp watches for the
/// signal and asks these functions who speaks and what.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rb {

/// Where one rank runs: its machine and its process id, gathered from every rank at the start.
struct RankPlace {
    std::string host;
    int pid = 0;
};

/// The ranks whose process is gone, among those on `host` (the only ones a process can look
/// at), by `gone(pid)`.
std::vector<int> goneRanks(const std::vector<RankPlace>& places, const std::string& host,
                           const std::function<bool(int pid)>& gone);

/// True when rank `rank` speaks for the job: rank 0 always, another rank only when every rank
/// below it is on its machine and gone (`gone`, from goneRanks).
bool speaksForJob(int rank, const std::vector<RankPlace>& places, const std::vector<int>& gone);

/// The image being rendered when the job ended, as the end message tells it.
struct JournalNote {
    std::string journal;               ///< The journal's path.
    std::optional<std::size_t> tiles;  ///< The tiles it holds; unknown: not counted.
    std::size_t of = 0;                ///< The tiles of the whole image.
};

/// What the journal holds and the command that renders the rest, for a message that says
/// why the render stopped.
std::string journalSentence(const JournalNote& journal, const std::string& resumeCommand);

/// The one line said when mpirun ended the job, without "rt: ": which ranks were lost (else
/// that the job was stopped), what the journal of the image being rendered holds, if any, and
/// the command that renders the rest.
std::string jobEndMessage(const std::vector<int>& gone, const std::vector<RankPlace>& places,
                          const std::string& host, const std::optional<JournalNote>& journal,
                          const std::string& resumeCommand);

/// The command that resumes this run: `mpirun -np RANKS` and rt's own arguments with
/// --resume, each quoted for a POSIX shell where needed.
std::string resumeCommand(int ranks, const std::vector<std::string>& arguments);

}  // namespace rb
