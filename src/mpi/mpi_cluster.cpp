#include "mpi/mpi_cluster.h"

#include <fcntl.h>
#include <mpi.h>
#include <omp.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <deque>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "core/error.h"
#include "core/interrupt.h"
#include "core/render.h"
#include "core/single_process.h"

namespace rb {
namespace {

// Message tags of the tile exchange.
constexpr int kTagLease = 1;   // rank 0 -> worker: tile positions; none means "stop"
constexpr int kTagResult = 2;  // worker -> rank 0: a finished lease (or its failure)
constexpr int kTagDone = 3;    // worker -> rank 0: its rays and busy time, after its last lease
// A lease's answer says first what became of it; only a rendered lease carries pixels.
constexpr std::int32_t kLeaseRendered = 0;  // every tile finished
constexpr std::int32_t kLeaseFailed = 1;    // a tile threw: the rank says why at the agreement
constexpr std::int32_t kLeaseStopped = 2;   // the rank's time limit came: no tile is kept
/// Leases a worker holds at once: it renders one while the answer to the last is on its way.
constexpr int kLeaseAhead = 3;
/// The most tiles in one lease, per thread of the rank that takes it.
constexpr int kMaxLeasePerThread = 8;

/// CPU seconds the calling thread has used (not wall time, so oversubscription does not blur it).
double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// The variables by which Open MPI, MPICH (Hydra) and PMIx launchers tell a process it is a rank.
constexpr const char* kLauncherVariables[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"};

/// True when mpirun (or mpiexec, srun) started this process.
bool startedByLauncher() {
    for (const char* name : kLauncherVariables)
        if (std::getenv(name)) return true;
    return false;
}

/// True when argv holds `option` (before the full parse, which may itself fail).
bool hasOption(int argc, char** argv, const std::string& option) {
    for (int i = 1; i < argc; ++i)
        if (argv[i] == option || std::string(argv[i]).rfind(option + "=", 0) == 0) return true;
    return false;
}

/// The seconds --tile-timeout gives, or 0 (automatic) without it. A bad value is read as 0
/// here: parseCommandLine refuses it, on every rank, before any tile is leased.
double tileTimeout(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const char* text = arg == "--tile-timeout" && i + 1 < argc ? argv[i + 1]
                           : arg.rfind("--tile-timeout=", 0) == 0  ? argv[i] + 15
                                                                   : nullptr;
        if (!text) continue;
        char* end = nullptr;
        const double seconds = std::strtod(text, &end);
        return *end == '\0' && std::isfinite(seconds) && seconds > 0 ? seconds : 0.0;
    }
    return 0.0;
}

/// The value of --mpi-lease (dynamic, the default, or static).
LeasePolicy leasePolicy(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--mpi-lease=static" ||
            (arg == "--mpi-lease" && i + 1 < argc && std::string(argv[i + 1]) == "static"))
            return LeasePolicy::Static;
    }
    return LeasePolicy::Dynamic;
}

/// The film's pixels of `tile`, row by row.
std::vector<float> tilePixels(const Image& image, const ImageTile& tile) {
    std::vector<float> pixels;
    pixels.reserve(static_cast<std::size_t>(tile.pixels()) * 3);
    const std::span<const float> data = image.data();
    for (int y = tile.y0; y < tile.y1; ++y) {
        const std::size_t row = (static_cast<std::size_t>(y) * image.width() + tile.x0) * 3;
        pixels.insert(pixels.end(), data.begin() + static_cast<long>(row),
                      data.begin() + static_cast<long>(row + (tile.x1 - tile.x0) * 3));
    }
    return pixels;
}

/// Copy `pixels` (as tilePixels gives them) into the film at `tile`.
void placeTile(Image& image, const ImageTile& tile, const float* pixels) {
    const std::span<float> data = image.data();
    const std::size_t width = static_cast<std::size_t>(tile.x1 - tile.x0) * 3;
    for (int y = tile.y0; y < tile.y1; ++y, pixels += width)
        std::memcpy(&data[(static_cast<std::size_t>(y) * image.width() + tile.x0) * 3], pixels,
                    width * sizeof(float));
}

/// Append the bytes of `value` to `out`.
template <class T>
void put(std::vector<std::byte>& out, const T& value) {
    const auto* p = reinterpret_cast<const std::byte*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

/// Read a T from `in` at `at`, advancing it.
template <class T>
T take(const std::vector<std::byte>& in, std::size_t& at) {
    T value;
    std::memcpy(&value, in.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

/// Receive the next message from `source` with `tag` (any, with MPI_ANY_*), whole.
std::vector<std::byte> receive(int source, int tag, MPI_Status* status) {
    MPI_Probe(source, tag, MPI_COMM_WORLD, status);
    int count = 0;
    MPI_Get_count(status, MPI_BYTE, &count);
    std::vector<std::byte> bytes(static_cast<std::size_t>(count));
    MPI_Recv(bytes.data(), count, MPI_BYTE, status->MPI_SOURCE, status->MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return bytes;
}

/// Send `bytes` to `dest` with `tag`; returns the bytes sent.
std::uint64_t send(const std::vector<std::byte>& bytes, int dest, int tag) {
    MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD);
    return bytes.size();
}

/// True when the process `pid` (of this machine) is gone: no such process, or a zombie.
bool processGone(int pid) {
    if (kill(pid, 0) != 0 && errno == ESRCH) return true;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    std::getline(stat, line);
    const std::size_t state = line.rfind(") ");  // the state follows the command's name
    return state != std::string::npos && state + 2 < line.size() && line[state + 2] == 'Z';
}

/// Every rank's machine and process id, on every rank.
std::vector<RankPlace> gatherPlaces(int size) {
    struct Place {
        int pid;
        char host[256];
    };
    Place mine{static_cast<int>(getpid()), {}};
    gethostname(mine.host, sizeof mine.host - 1);
    std::vector<Place> all(static_cast<std::size_t>(size));
    MPI_Allgather(&mine, sizeof(Place), MPI_BYTE, all.data(), sizeof(Place), MPI_BYTE,
                  MPI_COMM_WORLD);
    std::vector<RankPlace> places;
    for (const Place& p : all) places.push_back({p.host, p.pid});
    return places;
}

/// A lease: its tile count, then the positions.
std::vector<std::byte> leaseMessage(const std::vector<int>& positions) {
    std::vector<std::byte> bytes;
    put(bytes, static_cast<std::int32_t>(positions.size()));
    for (int p : positions) put(bytes, static_cast<std::int32_t>(p));
    return bytes;
}

/// The positions of a lease message.
std::vector<int> leasePositions(const std::vector<std::byte>& bytes) {
    std::size_t at = 0;
    std::vector<int> positions(static_cast<std::size_t>(take<std::int32_t>(bytes, at)));
    for (int& p : positions) p = take<std::int32_t>(bytes, at);
    return positions;
}

/// "tile 17 (pixels 32..47 x 16..31)": a tile by its position in render order and its film
/// rectangle (first..last column x first..last row).
std::string tileName(int position, const ImageTile& tile) {
    return "tile " + std::to_string(position) + " (pixels " + std::to_string(tile.x0) + ".." +
           std::to_string(tile.x1 - 1) + " x " + std::to_string(tile.y0) + ".." +
           std::to_string(tile.y1 - 1) + ")";
}

/// "rank 2 (host h, pid 123)".
std::string rankName(int rank, const RankPlace& place) {
    return "rank " + std::to_string(rank) + " (host " + place.host + ", pid " +
           std::to_string(place.pid) + ")";
}

/// A tile's failure, said with the rank and the tile it happened on.
struct TileFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The exception being handled, thrown by tile `position` on `rank`, as a TileFailure naming
/// both. A stopped render (RenderStopped, or a tile given up half-done: TileAbandoned) is no
/// tile's fault: it passes unchanged, with its exit code (exitCodeOf); any other failure ends rt
/// with 1, as before.
std::exception_ptr tileFailure(int rank, const RankPlace& place, int position,
                               const ImageTile& tile) {
    std::string what;
    try {
        throw;
    } catch (const RenderStopped&) {
        return std::current_exception();
    } catch (const TileAbandoned&) {
        return std::current_exception();
    } catch (const std::bad_alloc&) {
        what = "out of memory";
    } catch (const std::exception& e) {
        what = e.what();
    } catch (...) {
        what = "an exception of unknown type";
    }
    return std::make_exception_ptr(TileFailure(rankName(rank, place) + " failed on " +
                                               tileName(position, tile) + ": " + what));
}

/// True when `failure` is a tile given up half-done because the render is to stop (--time-limit
/// asked after a pixel): the lease holding it is neither journaled nor sent back.
bool abandoned(const std::exception_ptr& failure) {
    if (!failure) return false;
    try {
        std::rethrow_exception(failure);
    } catch (const TileAbandoned&) {
        return true;
    } catch (...) {
        return false;
    }
}

#ifdef RB_FAULT_INJECTION
/// Test builds only (rt_fault, tests/mpi/fault.py): RB_FAULT=rank:R,tile:K,kind:throw|hang makes
/// tile K throw, or never finish, when rank R renders it. rt itself has no such hook.
void injectFault(int rank, int position) {
    static const std::string fault = std::getenv("RB_FAULT") ? std::getenv("RB_FAULT") : "";
    if (fault.empty() ||
        fault.rfind("rank:" + std::to_string(rank) + ",tile:" + std::to_string(position) + ",kind:",
                    0) != 0)
        return;
    if (fault.ends_with(":hang"))
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    throw std::runtime_error("injected fault (RB_FAULT=" + fault + ")");
}
#endif

/// What a worker sends after its last lease.
struct WorkerReport {
    RayCounters rays;
    RankWork work;
};

/// Busy-time accounting for one batch: each thread adds the CPU time of its tiles.
struct BatchClock {
    std::vector<double> seconds;
    explicit BatchClock(int threads) : seconds(static_cast<std::size_t>(threads), 0.0) {}
    double total() const { return std::accumulate(seconds.begin(), seconds.end(), 0.0); }
};

/// Render the tiles at `positions` in parallel on `rank`; returns the first failure (null: none),
/// naming the rank and the tile, and marks each tile that finished in `finished` (when given:
/// an entry per position). The main thread (OpenMP thread 0, the one MPI may be called from)
/// runs `between` after each of its tiles.
std::exception_ptr renderBatch(const TileWork& work, const std::vector<int>& positions,
                               Image& image, std::vector<RayCounters>& rays, BatchClock& clock,
                               const std::function<void()>& between, int rank,
                               const RankPlace& place, std::vector<char>* finished = nullptr) {
    std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1) num_threads(work.threads)
    for (int i = 0; i < static_cast<int>(positions.size()); ++i) {
        const int thread = omp_get_thread_num();
        try {
            const double start = threadCpuSeconds();
            const std::uint64_t raysBefore = rays[thread].total();
            work.tileStarted(positions[i]);
#ifdef RB_FAULT_INJECTION
            injectFault(rank, positions[i]);
#endif
            work.renderTile(positions[i], image, rays[thread]);
            work.tileFinished(positions[i], rays[thread].total() - raysBefore);
            if (finished) (*finished)[static_cast<std::size_t>(i)] = 1;
            clock.seconds[thread] += threadCpuSeconds() - start;
            if (thread == 0 && between) between();
        } catch (...) {
            std::exception_ptr e = tileFailure(rank, place, positions[i],
                                               work.tiles[static_cast<std::size_t>(positions[i])]);
#pragma omp critical(rb_mpi_failure)
            if (!failure) failure = e;
        }
    }
    return failure;
}

}  // namespace

MpiCluster::MpiCluster(int argc, char** argv, LeasePolicy policy)
    : policy_(policy), tileTimeout_(tileTimeout(argc, argv)) {
    // Ctrl-C and SIGTERM wait, pending, for the watcher. They are held before MPI_Init: the
    // threads Open MPI starts there inherit the mask, and one that did not hold them would take
    // the signal and end the rank at once, silently.
    holdInterrupts();
    int provided = 0;
    // Only the main thread calls MPI (between its own tiles), so FUNNELED is enough.
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    // Processes this rank starts (--batch's children) are no ranks of their own.
    for (const char* name : kLauncherVariables) unsetenv(name);
    if (rank_ != 0) {
        // Every rank says the same warnings and lines: only rank 0 speaks. The others keep
        // their stderr for an error that is theirs alone.
        const int saved = dup(STDERR_FILENO);
        if (saved >= 0) errors_ = fdopen(saved, "w");
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
            close(null);
        }
    }
    places_ = gatherPlaces(size_);
    resumeCommand_ = resumeCommand(size_, std::vector<std::string>(argv, argv + argc));
    watcher_ = std::thread([this] { watch(); });
}

MpiCluster::~MpiCluster() {
    {
        std::lock_guard lock(mutex_);
        closing_ = true;
    }
    wake_.notify_all();
    watcher_.join();
    MPI_Finalize();
}

void MpiCluster::watch() {
    std::unique_lock lock(mutex_);
    while (!closing_) {
        if (pendingInterrupt()) {
            lock.unlock();
            endJob();
        }
        if (ownLeaseOverdue()) {
            // Copied under the lock: the main thread may yet finish the lease and clear it.
            const OwnLease own = *ownLease_;
            lock.unlock();
            endForOwnHang(own);
        }
        wake_.wait_for(lock, std::chrono::milliseconds(10));
    }
}

void MpiCluster::endJob() {
    ending_ = true;
    // Step 1: the ranks of this machine that are gone; the rank that speaks says why, with
    // the journal locked, so rank 0 journals nothing after the count it gives.
    const std::string& host = places_[static_cast<std::size_t>(rank_)].host;
    const std::vector<int> gone = goneRanks(places_, host, processGone);
    std::unique_lock lock(mutex_, std::defer_lock);
    // Rank 0 stays silent when it ended the job itself, having said why (endForHang).
    if (!said_ && speaksForJob(rank_, places_, gone)) {
        lock.lock();
        if (rank_ == 0) writeJournalPartial();
        std::fprintf(errors_, "rt: %s\n",
                     jobEndMessage(gone, places_, host, journalNote(), resumeCommand_).c_str());
        std::fflush(errors_);
    }
    // Step 2: stay until mpirun's SIGKILL (a second after its SIGTERM), so that no other rank,
    // looking for the lost one, finds this one gone. Alone, no one else is looking.
    if (size_ > 1) std::this_thread::sleep_for(std::chrono::seconds(5));
    std::_Exit(1);
}

void MpiCluster::writeJournalPartial() {
    if (!rendering_ || !rendering_->partial) return;
    // The finished tiles are the journal's (the film may still be written by render threads).
    try {
        const Rendering& r = *rendering_;
        PartialImage partial{Image(r.width, r.height), 0, r.tiles.size()};
        for (const JournalTile& t : readJournal(journalPath(r.identity.output), r.identity))
            if (const auto k = static_cast<std::size_t>(t.position); k < r.tiles.size()) {
                placeTile(*partial.image, r.tiles[k], t.pixels.data());
                ++partial.tilesDone;
            }
        writePartial(partial, r.identity.output, errors_);
    } catch (const std::exception& e) {
        std::fprintf(errors_, "rt: --partial: %s\n", e.what());
    }
}

void MpiCluster::sayHang(const std::vector<HungRank>& hung, double limit, const TileWork& work) {
    // Name each hung rank and the tiles of the lease it is rendering; every tile the other
    // ranks returned is in the journal already, flushed to the kernel.
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g s", limit);
    const std::string why = tileTimeout_ > 0 ? " (--tile-timeout)"
                                             : " (50 times the slowest lease so far, at least "
                                               "300 s; --tile-timeout sets it)";
    std::string text;
    for (const HungRank& h : hung) {
        std::string tiles;
        for (int p : h.tiles)
            tiles +=
                (tiles.empty() ? "" : ", ") + tileName(p, work.tiles[static_cast<std::size_t>(p)]);
        text +=
            (text.empty() ? "" : "; ") +
            rankName(h.rank, places_[static_cast<std::size_t>(h.rank)]) +
            (h.rank == 0 ? " has finished nothing for over " : " has returned nothing for over ") +
            seconds + why + " while rendering " + tiles;
    }
    std::lock_guard lock(mutex_);
    said_ = true;
    writeJournalPartial();
    std::fprintf(errors_, "rt: %s, so the job stops without writing an image; %s\n", text.c_str(),
                 journalSentence(*journalNote(), resumeCommand_).c_str());
    std::fflush(errors_);
}

void MpiCluster::endForHang(const std::vector<HungRank>& hung, double limit, const TileWork& work) {
    // Step 1: say which ranks hung, on which tiles.
    sayHang(hung, limit, work);
    // Step 2: end the job. A hung rank can take part in no collective call, MPI_Finalize
    // included. One on this machine gets SIGTERM: its watcher exits (silently: rank 0 is alive),
    // and mpirun then ends the others, this rank's watcher exiting 1 without a second word.
    // A hung rank elsewhere is out of reach: MPI_Abort ends the job (a rank of this machine
    // may then add that rank 0 was lost).
    bool remote = false;
    for (const HungRank& h : hung) {
        const RankPlace& place = places_[static_cast<std::size_t>(h.rank)];
        if (place.host == places_[0].host)
            kill(place.pid, SIGTERM);
        else
            remote = true;
    }
    if (remote) MPI_Abort(MPI_COMM_WORLD, 1);
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
}

bool MpiCluster::ownLeaseOverdue() const {
    if (!ownLease_ || !std::isfinite(ownLease_->limit)) return false;
    const auto elapsed = std::chrono::steady_clock::now() - ownLease_->start;
    return std::chrono::duration<double>(elapsed).count() > ownLease_->limit;
}

void MpiCluster::endForOwnHang(const OwnLease& own) {
    // Step 1: rank 0's own lease is overdue: say so, as for a worker.
    sayHang({{0, own.tiles}}, own.limit, *own.work);
    // Step 2: end the job without an MPI call (only the main thread may make one, and it is the
    // hung one). The workers of this machine get SIGTERM and exit silently, since rank 0 is
    // still alive when their watchers look; rank 0 waits until they are gone (at most 30 s),
    // then exits 1, and mpirun ends the rest (a rank on another machine may add that rank 0 was
    // lost).
    std::vector<int> local;
    for (int r = 1; r < size_; ++r) {
        const RankPlace& place = places_[static_cast<std::size_t>(r)];
        if (place.host != places_[0].host) continue;
        kill(place.pid, SIGTERM);
        local.push_back(place.pid);
    }
    const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < giveUp &&
           !std::all_of(local.begin(), local.end(), processGone))
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::_Exit(1);
}

std::optional<JournalNote> MpiCluster::journalNote() const {
    if (!rendering_) return std::nullopt;
    JournalNote note{journalPath(rendering_->identity.output), std::nullopt,
                     rendering_->tiles.size()};
    if (rank_ == 0) {
        note.tiles = journaled_;
    } else {
        try {  // rank 0 is gone: its journal, if it got as far as writing one, says
            note.tiles = readJournal(note.journal, rendering_->identity).size();
        } catch (const InputError&) {
        }
    }
    return note;
}

void MpiCluster::journalTile(int position, std::span<const float> pixels) {
    std::lock_guard lock(mutex_);
    journal_->append(position, pixels);
    ++journaled_;
}

void MpiCluster::parkIfEnding() const {
    while (ending_ || pendingInterrupt()) std::this_thread::sleep_for(std::chrono::seconds(1));
}

void MpiCluster::agree(std::exception_ptr failure) {
    parkIfEnding();
    // Step 1: the lowest rank that failed (size_: none).
    const int mine = failure ? rank_ : size_;
    int first = size_;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == size_) return;
    // Step 2: its exit code ends every rank; only it says why.
    int code = first == rank_ ? exitCodeOf(failure) : 0;
    MPI_Bcast(&code, 1, MPI_INT, first, MPI_COMM_WORLD);
    throw AgreedFailure{code, first == rank_ ? failure : nullptr};
}

void MpiCluster::checkSameRender(const RenderIdentity& identity) const {
    std::uint64_t hash = fnv1a64({});
    for (const auto& [name, value] : identity.fields) {
        const std::string line = name + "=" + value + "\n";
        hash = fnv1a64({reinterpret_cast<const unsigned char*>(line.data()), line.size()}, hash);
    }
    std::uint64_t low = 0, high = 0;
    MPI_Allreduce(&hash, &low, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&hash, &high, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
    if (low != high)
        throw InputError(identity.output +
                         ": the ranks were given different renders (their scene, size, seed or "
                         "options differ); every rank must run the same command");
}

void MpiCluster::renderTiles(const TileWork& work, Image& image, RayCounters& counters) {
    threads_ = work.threads;
    filmBytes_ = static_cast<std::uint64_t>(image.width()) * image.height() * 3 * sizeof(float);
    // Step 1: rank 0 reads the journal (--resume) and starts a new one; the tiles it holds are
    // in the film already, the others are to render.
    std::exception_ptr failure;
    std::vector<int> todo;
    if (rank_ == 0) {
        try {
            const std::string path = journalPath(work.identity.output);
            std::vector<JournalTile> kept;
            const bool resumed = work.resume && std::filesystem::exists(path);
            if (resumed)
                kept = readJournal(path, work.identity);
            else if (work.resume)
                std::fprintf(stderr, "rt: --resume: no journal %s; rendering the whole image\n",
                             path.c_str());
            std::vector<bool> done(work.tiles.size(), false);
            for (const JournalTile& t : kept) {
                const std::size_t k = static_cast<std::size_t>(t.position);
                if (k >= work.tiles.size() ||
                    t.pixels.size() != static_cast<std::size_t>(work.tiles[k].pixels()) * 3)
                    throw InputError("--resume: the journal " + path + " holds a tile (" +
                                     std::to_string(t.position) + ") this image does not have");
                placeTile(image, work.tiles[k], t.pixels.data());
                done[k] = true;
                work.tileStarted(t.position);  // the progress bar counts it as done
                work.tileFinished(t.position, 0);
            }
            journal_ = std::make_unique<JournalWriter>(path, work.identity, kept);
            {
                std::lock_guard lock(mutex_);
                rendering_ = Rendering{work.identity, work.tiles, image.width(), image.height(),
                                       work.partial};
                journaled_ = kept.size();
            }
            for (std::size_t k = 0; k < work.tiles.size(); ++k)
                if (!done[k]) todo.push_back(static_cast<int>(k));
            if (resumed)
                std::fprintf(stderr,
                             "rt: --resume: reused %zu of %zu tiles from %s; rendering the other "
                             "%zu\n",
                             kept.size(), work.tiles.size(), path.c_str(), todo.size());
            // A static split deals contiguous bands of the image: scanline order.
            if (policy_ == LeasePolicy::Static)
                std::stable_sort(todo.begin(), todo.end(), [&](int a, int b) {
                    const ImageTile &s = work.tiles[a], &t = work.tiles[b];
                    return std::tie(s.y0, s.x0) < std::tie(t.y0, t.x0);
                });
        } catch (...) {
            failure = std::current_exception();
        }
    } else {
        std::lock_guard lock(mutex_);
        rendering_ = Rendering{work.identity, work.tiles, image.width(), image.height(), false};
    }
    std::vector<int> threads(static_cast<std::size_t>(size_));
    try {
        agree(failure);
        checkSameRender(work.identity);
        // Leases are sized by each rank's threads (--threads may differ between machines).
        MPI_Allgather(&work.threads, 1, MPI_INT, threads.data(), 1, MPI_INT, MPI_COMM_WORLD);
    } catch (...) {
        // A run that never started leaves no journal; a resumed one keeps the tiles it had.
        if (journal_ && !work.resume) journal_->discard();
        journal_.reset();
        throw;
    }
    // Step 2: the exchange; a rank that fails goes on answering until every rank is done.
    try {
        if (rank_ == 0)
            lead(work, image, counters, todo, threads);
        else
            follow(work, image, counters);
    } catch (const RenderStopped&) {
        // Rank 0 was stopped: the others learn it at their next agreement.
        throw;
    } catch (...) {
        failure = std::current_exception();
    }
    // Step 3: every rank learns whether another failed before rank 0 writes anything. A tile's
    // failure also says what the journal holds (rank 0 journals nothing after this agreement)
    // and how to render the rest.
    try {
        agree(failure);
    } catch (AgreedFailure& agreed) {
        try {
            if (agreed.cause) std::rethrow_exception(agreed.cause);
        } catch (const TileFailure& e) {
            std::lock_guard lock(mutex_);
            agreed.cause = std::make_exception_ptr(TileFailure(
                std::string(e.what()) + "; " + journalSentence(*journalNote(), resumeCommand_)));
        } catch (...) {
        }
        throw;
    }
}

void MpiCluster::lead(const TileWork& work, Image& image, RayCounters& counters,
                      const std::vector<int>& todo, const std::vector<int>& threads) {
    using Clock = std::chrono::steady_clock;
    LeaseSchedule schedule(todo, threads, policy_);
    work_.assign(static_cast<std::size_t>(size_), RankWork{});
    std::exception_ptr failure;
    bool stopping = false, remoteFailed = false;
    std::uint64_t sentByRank0 = 0;
    // A hung rank: each worker's leases not yet returned (oldest first: it renders them in
    // order), and when rank 0 last heard from it; the longest any lease took so far.
    std::vector<std::deque<std::vector<int>>> held(static_cast<std::size_t>(size_));
    std::vector<Clock::time_point> heard(static_cast<std::size_t>(size_), Clock::now());
    double slowest = 0.0;
    std::vector<bool> reported(static_cast<std::size_t>(size_), false);
    std::vector<HungRank> hung;
    auto isHung = [&](int w) {
        return std::any_of(hung.begin(), hung.end(),
                           [&](const HungRank& h) { return h.rank == w; });
    };

    // What a worker gets next: a lease, or none once the render is ending.
    auto nextLease = [&](int worker) {
        const bool ending = stopping || failure || remoteFailed || !hung.empty();
        std::vector<int> lease =
            ending ? std::vector<int>{} : schedule.next(worker, kMaxLeasePerThread);
        for (int p : lease) work.tileStarted(p);
        auto& queue = held[static_cast<std::size_t>(worker)];
        if (queue.empty()) heard[static_cast<std::size_t>(worker)] = Clock::now();
        if (!lease.empty()) queue.push_back(lease);
        return lease;
    };
    // The seconds a worker may go without returning a lease it holds. --tile-timeout gives
    // them; otherwise none until some lease has finished (nothing to compare with yet), then 50
    // times the slowest lease so far, and at least 300 s. A lease is a few tiles per thread:
    // one 50 times slower than any other is no uneven scene but a hang, while a loaded or
    // oversubscribed machine can pause a rank for seconds, so a short render, whose leases
    // take milliseconds, must not stop for that; and a slow scene's leases raise the limit.
    auto overdueAfter = [&] {
        if (tileTimeout_ > 0) return tileTimeout_;
        return slowest > 0 ? std::max(300.0, 50 * slowest) : HUGE_VAL;
    };
    // Take in one message, if one is waiting: a finished lease (answered with the next) or a
    // worker's report.
    auto serveOne = [&] {
        MPI_Status status;
        int waiting = 0;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
        if (!waiting) return false;
        const std::vector<std::byte> bytes = receive(MPI_ANY_SOURCE, MPI_ANY_TAG, &status);
        const int worker = status.MPI_SOURCE;
        RankWork& share = work_[static_cast<std::size_t>(worker)];
        share.bytesSent += bytes.size();
        std::size_t at = 0;
        if (status.MPI_TAG == kTagDone) {
            const WorkerReport report = take<WorkerReport>(bytes, at);
            counters.merge(report.rays);
            share.tiles = report.work.tiles;
            share.busySeconds = report.work.busySeconds;
            reported[static_cast<std::size_t>(worker)] = true;
            return true;
        }
        // The lease it rendered is its oldest; the next (if any) started as it sent this one.
        const Clock::time_point now = Clock::now();
        auto& queue = held[static_cast<std::size_t>(worker)];
        if (!queue.empty()) queue.pop_front();
        slowest = std::max(
            slowest,
            std::chrono::duration<double>(now - heard[static_cast<std::size_t>(worker)]).count());
        heard[static_cast<std::size_t>(worker)] = now;
        // A finished lease: [status][count][rays][positions][pixels of each tile, in order];
        // the pixels only when the status is kLeaseRendered.
        const std::int32_t leaseStatus = take<std::int32_t>(bytes, at);
        const std::int32_t count = take<std::int32_t>(bytes, at);
        std::uint64_t leaseRays = take<std::uint64_t>(bytes, at);
        std::vector<int> positions(static_cast<std::size_t>(count));
        for (int& p : positions) p = take<std::int32_t>(bytes, at);
        if (leaseStatus == kLeaseFailed) remoteFailed = true;
        // A worker's time limit came first: the render stops, as when rank 0's does.
        if (leaseStatus == kLeaseStopped) stopping = true;
        for (int p : positions) {
            if (leaseStatus != kLeaseRendered) break;
            const ImageTile& tile = work.tiles[static_cast<std::size_t>(p)];
            const auto* pixels = reinterpret_cast<const float*>(bytes.data() + at);
            placeTile(image, tile, pixels);
            work.tileFinished(p, std::exchange(leaseRays, 0));
            at += static_cast<std::size_t>(tile.pixels()) * 3 * sizeof(float);
            // A journal that cannot be written fails the render, which still ends in order.
            try {
                if (!failure) journalTile(p, {pixels, static_cast<std::size_t>(tile.pixels()) * 3});
            } catch (...) {
                failure = std::current_exception();
            }
        }
        sentByRank0 += send(leaseMessage(nextLease(worker)), worker, kTagLease);
        return true;
    };
    // Take in every waiting message, then look for workers that are overdue: only then, since
    // a result rank 0 had not yet taken in (busy with its own tile) is no sign of a hang.
    auto serveWaiting = [&] {
        while (serveOne()) {
        }
        const Clock::time_point now = Clock::now();
        for (int w = 1; w < size_; ++w) {
            const auto k = static_cast<std::size_t>(w);
            if (!held[k].empty() && !isHung(w) &&
                std::chrono::duration<double>(now - heard[k]).count() > overdueAfter())
                hung.push_back({w, held[k].front()});
        }
    };

    // Step 1: every worker gets its first leases, so it starts at once and never waits.
    for (int w = 1; w < size_; ++w)
        for (int i = 0; i < kLeaseAhead; ++i)
            sentByRank0 += send(leaseMessage(nextLease(w)), w, kTagLease);
    // Step 2: rank 0 renders batches of its own, answering the workers between its tiles.
    std::vector<RayCounters> rays(static_cast<std::size_t>(work.threads));
    BatchClock clock(work.threads);
    const RankPlace& place = places_[0];
    while (!failure && !remoteFailed && hung.empty()) {
        if (work.shouldStop && work.shouldStop()) {
            stopping = true;
            break;
        }
        const std::vector<int> lease = schedule.next(0, kMaxLeasePerThread);
        if (lease.empty()) break;
        const Clock::time_point start = Clock::now();
        std::vector<char> finished(lease.size(), 0);
        // The watcher ends the job if this lease is overdue, as rank 0 does for a worker's.
        setOwnLease(OwnLease{lease, start, overdueAfter(), &work});
        const std::exception_ptr e =
            renderBatch(work, lease, image, rays, clock, serveWaiting, 0, place, &finished);
        setOwnLease(std::nullopt);
        // A tile given up half-done (the time limit, asked after a pixel) stops the render; it
        // is no failure.
        const bool stopped = abandoned(e);
        if (e && !stopped) failure = e;
        slowest = std::max(slowest, std::chrono::duration<double>(Clock::now() - start).count());
        if (failure) break;
        // The finished tiles go to the journal; a half-done one is blacked out of the film, as
        // the tiles not reached are, so that --partial's image holds the journal's tiles.
        try {
            for (std::size_t i = 0; i < lease.size(); ++i) {
                const ImageTile& tile = work.tiles[static_cast<std::size_t>(lease[i])];
                if (finished[i]) {
                    journalTile(lease[i], tilePixels(image, tile));
                    ++work_[0].tiles;
                } else {
                    const std::vector<float> black(static_cast<std::size_t>(tile.pixels()) * 3);
                    placeTile(image, tile, black.data());
                }
            }
        } catch (...) {
            failure = std::current_exception();
        }
        if (stopped) {
            stopping = true;
            break;
        }
        serveWaiting();
    }
    // Step 3: answer the workers until each has sent its report, or is hung. Polled, not a
    // blocking probe, so that a hung worker is seen.
    auto waitingFor = [&] {
        for (int w = 1; w < size_; ++w)
            if (!reported[static_cast<std::size_t>(w)] && !isHung(w)) return true;
        return false;
    };
    while (waitingFor()) {
        const std::size_t before = hung.size();
        serveWaiting();
        if (hung.size() == before) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (!hung.empty()) endForHang(hung, overdueAfter(), work);
    for (const RayCounters& r : rays) counters.merge(r);
    work_[0].busySeconds = clock.total();
    work_[0].bytesSent = sentByRank0;
    if (failure) std::rethrow_exception(failure);
    if (remoteFailed) return;  // the failing worker says why at the agreement that follows
    if (stopping) {
        std::lock_guard lock(mutex_);
        throw RenderStopped(journalSentence(*journalNote(), resumeCommand_), 1);
    }
}

void MpiCluster::follow(const TileWork& work, Image& image, RayCounters& counters) {
    std::deque<std::vector<int>> leases;
    MPI_Status status;
    for (int i = 0; i < kLeaseAhead; ++i)
        leases.push_back(leasePositions(receive(0, kTagLease, &status)));
    std::vector<RayCounters> rays(static_cast<std::size_t>(work.threads));
    BatchClock clock(work.threads);
    WorkerReport report;
    std::exception_ptr failure;
    bool stopped = false;
    // Render each lease and send it back; each result is answered by the next lease (or
    // none), which is taken in when it has arrived, or waited for once nothing else is left.
    int answersDue = 0;
    std::deque<std::pair<MPI_Request, std::vector<std::byte>>> sending;  // results in flight
    auto takeAnswer = [&] {
        leases.push_back(leasePositions(receive(0, kTagLease, &status)));
        --answersDue;
    };
    while (!leases.empty() || answersDue > 0) {
        if (leases.empty()) takeAnswer();
        const std::vector<int> lease = std::move(leases.front());
        leases.pop_front();
        if (lease.empty()) continue;
        const auto raysSoFar = [&] {
            std::uint64_t total = 0;
            for (const RayCounters& r : rays) total += r.total();
            return total;
        };
        const std::uint64_t raysBefore = raysSoFar();
        if (!failure && !stopped)
            failure = renderBatch(work, lease, image, rays, clock, nullptr, rank_,
                                  places_[static_cast<std::size_t>(rank_)]);
        // A tile given up half-done (this rank's time limit, asked after a pixel): this lease
        // and the ones still to come go back unrendered, and rank 0 stops the render.
        if (abandoned(failure)) {
            stopped = true;
            failure = nullptr;
        }
        std::vector<std::byte> result;
        put(result, failure ? kLeaseFailed : stopped ? kLeaseStopped : kLeaseRendered);
        put(result, static_cast<std::int32_t>(lease.size()));
        put(result, raysSoFar() - raysBefore);
        for (int p : lease) put(result, static_cast<std::int32_t>(p));
        if (!failure && !stopped) {
            for (int p : lease)
                for (float v : tilePixels(image, work.tiles[static_cast<std::size_t>(p)]))
                    put(result, v);
            report.work.tiles += lease.size();
        }
        // Sent without waiting: a lease of tiles is larger than Open MPI sends eagerly, and a
        // blocking send would wait until rank 0 finishes the tile it is rendering.
        report.work.bytesSent += result.size();
        sending.emplace_back(MPI_REQUEST_NULL, std::move(result));
        MPI_Isend(sending.back().second.data(), static_cast<int>(sending.back().second.size()),
                  MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD, &sending.back().first);
        for (int sent = 1; !sending.empty() && sent;) {
            MPI_Test(&sending.front().first, &sent, MPI_STATUS_IGNORE);
            if (sent) sending.pop_front();
        }
        ++answersDue;
        for (int arrived = 1; answersDue > 0 && arrived;) {
            MPI_Iprobe(0, kTagLease, MPI_COMM_WORLD, &arrived, &status);
            if (arrived) takeAnswer();
        }
    }
    for (auto& [request, bytes] : sending) MPI_Wait(&request, MPI_STATUS_IGNORE);
    // The report: counters holds this rank's pre-pass rays (its photon share) already.
    for (const RayCounters& r : rays) counters.merge(r);
    report.rays = counters;
    report.work.busySeconds = clock.total();
    std::vector<std::byte> bytes;
    put(bytes, report);
    send(bytes, 0, kTagDone);
    if (failure) std::rethrow_exception(failure);
}

void MpiCluster::imageWritten() {
    std::lock_guard lock(mutex_);
    if (journal_) journal_->discard();
    journal_.reset();
    rendering_.reset();
}

std::vector<std::byte> MpiCluster::joinInOrder(std::span<const std::byte> mine) {
    agree(nullptr);  // parks if the job is ending
    // Step 1: every rank's size, then every rank's bytes at its offset.
    const long long size = static_cast<long long>(mine.size());
    std::vector<long long> sizes(static_cast<std::size_t>(size_));
    MPI_Allgather(&size, 1, MPI_LONG_LONG, sizes.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD);
    std::vector<int> counts(sizes.size()), offsets(sizes.size());
    long long total = 0;
    for (std::size_t r = 0; r < sizes.size(); ++r) {
        offsets[r] = static_cast<int>(total);
        counts[r] = static_cast<int>(sizes[r]);
        total += sizes[r];
    }
    if (total > std::numeric_limits<int>::max())
        throw InputError("the ranks' shares are too large to join (over 2 GiB)");
    std::vector<std::byte> joined(static_cast<std::size_t>(total));
    MPI_Allgatherv(mine.data(), static_cast<int>(size), MPI_BYTE, joined.data(), counts.data(),
                   offsets.data(), MPI_BYTE, MPI_COMM_WORLD);
    joinBytes_ += static_cast<std::uint64_t>(size) * static_cast<std::uint64_t>(size_ - 1);
    return joined;
}

std::vector<std::vector<std::byte>> MpiCluster::gatherToFirst(std::span<const std::byte> mine) {
    agree(nullptr);
    const int size = static_cast<int>(mine.size());
    std::vector<int> sizes(static_cast<std::size_t>(size_));
    MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> offsets(sizes.size(), 0);
    std::partial_sum(sizes.begin(), sizes.end() - 1, offsets.begin() + 1);
    std::vector<std::byte> all(rank_ == 0 ? static_cast<std::size_t>(offsets.back() + sizes.back())
                                          : 0);
    MPI_Gatherv(mine.data(), size, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0,
                MPI_COMM_WORLD);
    if (rank_ != 0) return {};
    std::vector<std::vector<std::byte>> parts;
    for (std::size_t r = 0; r < sizes.size(); ++r)
        parts.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + sizes[r]);
    return parts;
}

std::vector<std::string> MpiCluster::statistics() const {
    if (work_.empty()) return {};
    // Bytes: every message of the tile exchange, both ways, against the film they carried.
    std::uint64_t bytes = 0;
    double busy = 0.0, most = 0.0;
    std::string busyList, tileList;
    char text[64];
    for (const RankWork& w : work_) {
        bytes += w.bytesSent;
        busy += w.busySeconds;
        most = std::max(most, w.busySeconds);
        std::snprintf(text, sizeof text, " %.3f", w.busySeconds);
        busyList += text;
        tileList += " " + std::to_string(w.tiles);
    }
    const double mean = busy / static_cast<double>(work_.size());
    std::vector<std::string> lines;
    char line[256];
    std::snprintf(line, sizeof line, "mpi        %d ranks x %d threads, %s leases", size_, threads_,
                  policy_ == LeasePolicy::Dynamic ? "dynamic" : "static");
    lines.emplace_back(line);
    std::snprintf(line, sizeof line,
                  "mpi        sent %llu bytes for a film of %llu (%.3fx); pre-pass joins %llu",
                  static_cast<unsigned long long>(bytes),
                  static_cast<unsigned long long>(filmBytes_),
                  filmBytes_ ? static_cast<double>(bytes) / static_cast<double>(filmBytes_) : 0.0,
                  static_cast<unsigned long long>(joinBytes_));
    lines.emplace_back(line);
    lines.push_back("mpi        busy cpu s per rank" + busyList);
    std::snprintf(line, sizeof line, "mpi        busy max/mean %.3f; tiles per rank",
                  mean > 0.0 ? most / mean : 1.0);
    lines.push_back(line + tileList);
    return lines;
}

std::unique_ptr<Cluster> joinCluster(int argc, char** argv) {
    if (startedByLauncher() || hasOption(argc, argv, "--mpi") || hasOption(argc, argv, "--resume"))
        return std::make_unique<MpiCluster>(argc, argv, leasePolicy(argc, argv));
    return std::make_unique<SingleProcess>();
}

}  // namespace rb
