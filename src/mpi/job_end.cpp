#include "mpi/job_end.h"

#include <algorithm>
#include <cctype>

namespace rb {
namespace {

/// "1", "1 and 2", "1, 2 and 3".
std::string listed(const std::vector<std::string>& items) {
    std::string text;
    for (std::size_t i = 0; i < items.size(); ++i)
        text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
    return text;
}

/// `word` quoted for a POSIX shell when it holds anything but safe characters.
std::string shellQuoted(const std::string& word) {
    const bool safe = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) ||
               std::string("-_./=,:+@%").find(c) != std::string::npos;
    });
    if (safe) return word;
    std::string quoted = "'";
    for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

}  // namespace

std::vector<int> goneRanks(const std::vector<RankPlace>& places, const std::string& host,
                           const std::function<bool(int pid)>& gone) {
    std::vector<int> ranks;
    for (std::size_t r = 0; r < places.size(); ++r)
        if (places[r].host == host && gone(places[r].pid)) ranks.push_back(static_cast<int>(r));
    return ranks;
}

bool speaksForJob(int rank, const std::vector<RankPlace>& places, const std::vector<int>& gone) {
    // Rank 0 is alive when it asks; a rank below this one that is alive, or that runs on
    // another machine (where no one here can tell), speaks instead.
    for (int below = 0; below < rank; ++below)
        if (std::find(gone.begin(), gone.end(), below) == gone.end()) return false;
    return rank < static_cast<int>(places.size());
}

std::string jobEndMessage(const std::vector<int>& gone, const std::vector<RankPlace>& places,
                          const std::string& host, const std::optional<JournalNote>& journal,
                          const std::string& resumeCommand) {
    // Step 1: why the job ended.
    std::string text;
    if (!gone.empty()) {
        std::vector<std::string> ranks, pids;
        for (int r : gone) {
            ranks.push_back(std::to_string(r));
            pids.push_back(std::to_string(places[static_cast<std::size_t>(r)].pid));
        }
        const bool one = gone.size() == 1;
        text = std::string(one ? "rank " : "ranks ") + listed(ranks) +
               (one ? " (pid " : " (pids ") + listed(pids) + (one ? ") was" : ") were") +
               " lost, and mpirun ended the job";
    } else if (std::all_of(places.begin(), places.end(),
                           [&](const RankPlace& p) { return p.host == host; })) {
        text = "stopped by mpirun (Ctrl-C or SIGTERM)";
    } else {
        text = "mpirun ended the job: Ctrl-C, SIGTERM, or a rank lost on another machine";
    }
    // Step 2: what is kept, and how to go on.
    if (!journal) return text + "; no image was being rendered, so no tile was lost";
    return text + "; " + journalSentence(*journal, resumeCommand);
}

std::string journalSentence(const JournalNote& journal, const std::string& resumeCommand) {
    const std::string held = journal.tiles ? std::to_string(*journal.tiles) + " of " +
                                                 std::to_string(journal.of) + " tiles"
                                           : "the tiles finished so far";
    return "the journal " + journal.journal + " holds " + held + ", and `" + resumeCommand +
           "` renders the rest (on any number of ranks)";
}

std::string resumeCommand(int ranks, const std::vector<std::string>& arguments) {
    std::string command = "mpirun -np " + std::to_string(ranks);
    bool resumes = false;
    for (const std::string& a : arguments) {
        command += " " + shellQuoted(a);
        resumes = resumes || a == "--resume";
    }
    return resumes ? command : command + " --resume";
}

}  // namespace rb
