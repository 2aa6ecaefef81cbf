/// \file
/// Tests of what a rank says when mpirun ends the job (src/mpi/job_end.h).
///
/// The claims: only ranks of one's own machine are judged gone; rank 0 speaks while it lives,
/// and otherwise the lowest rank whose lower ranks are all known gone, so exactly one rank
/// speaks; the line names the lost ranks with their pids (else says the job was stopped), what
/// the journal holds and a command that resumes, quoted so a shell reads it back unchanged.
#include "mpi/job_end.h"

#include <catch2/catch.hpp>
#include <set>
#include <string>
#include <vector>

namespace {

/// Three ranks on "lab01" (pids 100, 101, 102) and one on "lab02" (pid 200).
std::vector<rb::RankPlace> lab() {
    return {{"lab01", 100}, {"lab01", 101}, {"lab01", 102}, {"lab02", 200}};
}

}  // namespace

SCENARIO("A rank judges gone only the ranks of its own machine", "[mpi]") {
    GIVEN("ranks on two machines, where pids 101 and 200 no longer exist") {
        const std::set<int> dead{101, 200};
        const auto gone = [&](int pid) { return dead.count(pid) > 0; };
        WHEN("a rank on lab01 looks") {
            THEN("it finds rank 1 gone; rank 3's pid 200 is another machine's") {
                CHECK(rb::goneRanks(lab(), "lab01", gone) == std::vector<int>{1});
            }
        }
        WHEN("the rank on lab02 looks") {
            THEN("it finds its own machine's pid 200, rank 3, gone") {
                CHECK(rb::goneRanks(lab(), "lab02", gone) == std::vector<int>{3});
            }
        }
    }
}

SCENARIO("Exactly one surviving rank speaks for the job", "[mpi]") {
    GIVEN("three ranks on one machine") {
        const std::vector<rb::RankPlace> places = {{"m", 1}, {"m", 2}, {"m", 3}};
        WHEN("rank 2 is lost") {
            THEN("rank 0 speaks, rank 1 does not") {
                CHECK(rb::speaksForJob(0, places, {2}));
                CHECK_FALSE(rb::speaksForJob(1, places, {2}));
            }
        }
        WHEN("rank 0 is lost") {
            THEN("rank 1 speaks, rank 2 does not") {
                CHECK(rb::speaksForJob(1, places, {0}));
                CHECK_FALSE(rb::speaksForJob(2, places, {0}));
            }
        }
        WHEN("ranks 0 and 1 are lost") {
            THEN("rank 2 speaks") {
                CHECK(rb::speaksForJob(2, places, {0, 1}));
            }
        }
        WHEN("none is lost (Ctrl-C)") {
            THEN("rank 0 alone speaks") {
                CHECK(rb::speaksForJob(0, places, {}));
                CHECK_FALSE(rb::speaksForJob(1, places, {}));
                CHECK_FALSE(rb::speaksForJob(2, places, {}));
            }
        }
    }
}

SCENARIO("The end line says why, what the journal holds and how to resume", "[mpi]") {
    const std::string resume = "mpirun -np 3 ./rt scene.lua --resume";
    const rb::JournalNote journal{"out.png.journal", 57, 360};
    GIVEN("rank 2 lost on one machine") {
        THEN("the line names it, its pid, the journal's tiles and the command") {
            CHECK(rb::jobEndMessage({2}, lab(), "lab01", journal, resume) ==
                  "rank 2 (pid 102) was lost, and mpirun ended the job; the journal "
                  "out.png.journal holds 57 of 360 tiles, and `mpirun -np 3 ./rt scene.lua "
                  "--resume` renders the rest (on any number of ranks)");
        }
    }
    GIVEN("ranks 0 and 1 lost, and a journal that could not be counted") {
        const rb::JournalNote uncounted{"out.png.journal", std::nullopt, 360};
        THEN("both are named, and the journal holds the tiles finished so far") {
            CHECK(
                rb::jobEndMessage({0, 1}, lab(), "lab01", uncounted, resume)
                    .rfind("ranks 0 and 1 (pids 100 and 101) were lost, and mpirun ended the job; "
                           "the journal out.png.journal holds the tiles finished so far",
                           0) == 0);
        }
    }
    GIVEN("no rank lost") {
        const std::vector<rb::RankPlace> one = {{"m", 1}, {"m", 2}};
        THEN("on one machine the job was stopped (Ctrl-C or SIGTERM)") {
            CHECK(rb::jobEndMessage({}, one, "m", journal, resume)
                      .rfind("stopped by mpirun (Ctrl-C or SIGTERM); the journal", 0) == 0);
        }
        THEN("across machines a rank elsewhere may have been lost") {
            CHECK(rb::jobEndMessage({}, lab(), "lab01", journal, resume)
                      .rfind("mpirun ended the job: Ctrl-C, SIGTERM, or a rank lost on another "
                             "machine; ",
                             0) == 0);
        }
        THEN("with no render in progress, no tile was lost") {
            CHECK(rb::jobEndMessage({}, one, "m", std::nullopt, resume) ==
                  "stopped by mpirun (Ctrl-C or SIGTERM); no image was being rendered, so no "
                  "tile was lost");
        }
    }
}

SCENARIO("The resume command is the run's own, with --resume, quoted for a shell", "[mpi]") {
    GIVEN("arguments with a space and a quote") {
        THEN("they are single-quoted, a quote as '\\''") {
            CHECK(rb::resumeCommand(2, {"./rt", "--output", "my image.png", "it's.lua"}) ==
                  "mpirun -np 2 ./rt --output 'my image.png' 'it'\\''s.lua' --resume");
        }
    }
    GIVEN("a run that resumed already") {
        THEN("--resume is not added twice") {
            CHECK(rb::resumeCommand(1, {"./rt", "--resume", "a.lua"}) ==
                  "mpirun -np 1 ./rt --resume a.lua");
        }
    }
}
