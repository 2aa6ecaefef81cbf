// ./rt --batch DIR: render a class's scenes, each in a child rt, and write one HTML report.
//
// The batch runs in four steps. It finds every Lua file under DIR and sets aside the helpers
// (modules that parse and never call gr.render). It runs each scene as a child process of this same
// binary, in the scene's own folder, a few at a time, killing any child that outlives the
// per-scene time limit. It reads what each child printed on stderr (errors, warnings, and the
// --stats block, which names the era and every image written) into a SceneResult. And it
// writes DIR/raybook-report.html, one self-contained page with a card per scene, while the
// children's full logs stay in DIR/raybook-report/.
//
// The batch writes nothing outside DIR/raybook-report/ and that page. Each child renders with
// --output-dir DIR/raybook-report/SCENE.lua/, so a student's own image of the name the scene
// renders (an A4 deliverable) is never written over: the report shows it beside raybook's
// render, with the RMSE between them. A report folder or page that the batch did not make is
// never removed or replaced.
#include "app/batch.h"

#include <fcntl.h>
#include <stb_image.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <lua.hpp>
#include <map>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/html.h"
#include "core/error.h"

namespace rb {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// The folder under DIR that holds the children's logs; the batch owns it.
constexpr const char* kReportFolder = "raybook-report";
/// The report page, written in DIR.
constexpr const char* kReportPage = "raybook-report.html";
/// A file in the report folder that says the batch made it, so it may empty it next time.
constexpr const char* kReportStamp = ".raybook-batch";
/// A line in the report page's head that says the batch wrote it, so it may replace it.
constexpr const char* kReportGenerator = "<meta name=\"generator\" content=\"raybook --batch\">";

/// What became of one Lua file.
enum class Status { Ok, Error, TimedOut, Crashed, Helper };

/// How stdout and the report name each Status (in enum order), and the CSS class that colours it.
constexpr struct {
    const char* word;
    const char* cssClass;
} kStatusNames[] = {{"ok", "ok"},
                    {"error", "error"},
                    {"timed out", "timeout"},
                    {"crashed", "crash"},
                    {"skipped helper", "helper"}};

/// The words for a status, as stdout and the report show it.
const char* statusWord(Status s) {
    return kStatusNames[static_cast<int>(s)].word;
}
/// The CSS class of a status, which sets its colour.
const char* statusClass(Status s) {
    return kStatusNames[static_cast<int>(s)].cssClass;
}

/// One image a scene wrote, as the report shows it.
struct ImageInfo {
    std::string path;           ///< raybook's render, relative to DIR, '/'-separated.
    bool exists = false;        ///< The file was there after the batch.
    int width = 0, height = 0;  ///< From the PNG header, when readable.
    /// The student's own image of the name the scene renders, relative to DIR; empty if none.
    std::string own;
    std::string comparison;  ///< "RMSE 0.0123 ...", or why the two could not be compared.
};

/// Everything the batch learned about one Lua file.
struct SceneResult {
    std::string path;  ///< The scene's path relative to DIR, '/'-separated.
    Status status = Status::Ok;
    std::string note;          ///< How it ended, when that needs words ("exit code 2", a signal).
    double wallSeconds = 0;    ///< From start to exit, as the batch measured it.
    double renderSeconds = 0;  ///< The sum of --stats' "render X s" over its images.
    unsigned long long rays = 0;        ///< The sum of --stats' "(total N)" over its images.
    bool haveStats = false;             ///< At least one --stats block was printed.
    std::string era;                    ///< The era --stats names ("  era  current ...").
    std::vector<std::string> errors;    ///< "rt: error:" lines, without the prefix.
    std::vector<std::string> warnings;  ///< "rt: warning:" lines, without the prefix.
    /// --lenient: what the scene needed stand-ins for, one line per name or call (the list at
    /// the end of its stderr, without the "rt:   " prefix).
    std::vector<std::string> standIns;
    std::vector<std::string> other;     ///< Every other stderr line outside the stats.
    std::vector<ImageInfo> images;      ///< In the order the scene wrote them.
    std::string stdoutLog, stderrLog;   ///< The child's logs, relative to DIR.
    std::string renders;                ///< The folder of its renders, relative to DIR.
};

/// How one scene's child ended, as the rank that ran it saw it (sent to rank 0 under MPI).
struct ChildEnd {
    std::size_t index = 0;  ///< Into the results.
    bool started = true;    ///< False: fork failed, and `note` says why.
    int waitStatus = 0;     ///< From waitpid.
    bool killed = false;    ///< The batch sent SIGKILL for the time limit.
    double wallSeconds = 0;
    std::string note;
};

/// A child that is still running.
struct RunningChild {
    pid_t pid = 0;
    size_t index = 0;  ///< Into the results.
    Clock::time_point start;
    bool killed = false;  ///< The batch sent SIGKILL for the time limit.
};

/// How the batch runs, for the report's header.
struct BatchInfo {
    fs::path dir;               ///< DIR, absolute.
    int jobs = 1;               ///< Children at once.
    double timeLimit = 0;       ///< Seconds per scene.
    std::string passedOptions;  ///< The options every child got, as one line.
    std::string startedAt;      ///< Local date and time.
    double totalSeconds = 0;    ///< Wall time of the whole batch.
};

// ---- Finding scenes ---------------------------------------------------------------------------

/// The number of '=' of a Lua long bracket opening at text[i] ("[[", "[==["), or -1.
int longBracketLevel(const std::string& text, size_t i) {
    if (i >= text.size() || text[i] != '[') return -1;
    size_t j = i + 1;
    while (j < text.size() && text[j] == '=') ++j;
    return j < text.size() && text[j] == '[' ? static_cast<int>(j - i - 1) : -1;
}

/// The index just past the long bracket of `level` that closes at or after `from`.
size_t skipLongBracket(const std::string& text, size_t from, int level) {
    const std::string close = "]" + std::string(level, '=') + "]";
    const size_t end = text.find(close, from);
    return end == std::string::npos ? text.size() : end + close.size();
}

/// Lua source without its comments ("-- ..." and "--[[ ... ]]"); strings are kept whole, so
/// a "--" inside a string does not start a comment.
std::string stripLuaComments(const std::string& text) {
    std::string out;
    size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '-' && i + 1 < text.size() && text[i + 1] == '-') {
            // A comment: long if a long bracket follows, else to the end of the line.
            const int level = longBracketLevel(text, i + 2);
            if (level >= 0) {
                i = skipLongBracket(text, i + 2 + level + 2, level);
            } else {
                const size_t eol = text.find('\n', i);
                i = eol == std::string::npos ? text.size() : eol;
            }
            out += ' ';
        } else if (c == '\'' || c == '"') {
            // A short string: copy it up to its closing quote (or the end of the line).
            size_t j = i + 1;
            while (j < text.size() && text[j] != c && text[j] != '\n') j += text[j] == '\\' ? 2 : 1;
            j = std::min(j + 1, text.size());
            out.append(text, i, j - i);
            i = j;
        } else if (const int level = longBracketLevel(text, i); level >= 0) {
            const size_t j = skipLongBracket(text, i + level + 2, level);
            out.append(text, i, j - i);
            i = j;
        } else {
            out += c;
            ++i;
        }
    }
    return out;
}

/// The whole contents of a file ("" if it cannot be read).
std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// True when `text` compiles as a Lua chunk (it is not run).
bool parsesAsLua(const std::string& text) {
    lua_State* L = luaL_newstate();
    if (L == nullptr) throw std::bad_alloc();
    const bool parses = luaL_loadbufferx(L, text.data(), text.size(), "file", "t") == LUA_OK;
    lua_close(L);
    return parses;
}

/// True for a Lua file that is a helper, not a scene: it parses and its code never names
/// gr.render. A file that does not parse is a scene that failed, whatever it holds: its child
/// rt reports the syntax error with its line.
bool isHelper(const fs::path& file) {
    const std::string text = readFile(file);
    return stripLuaComments(text).find("gr.render") == std::string::npos && parsesAsLua(text);
}

/// Every *.lua under `dir`, relative and '/'-separated, sorted; hidden folders and the
/// batch's own report folder are not searched.
std::vector<std::string> findLuaFiles(const fs::path& dir) {
    std::vector<std::string> files;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path& p = it->path();
        const std::string name = p.filename().string();
        if (it->is_directory(ec)) {
            if (name == kReportFolder || name.starts_with(".")) it.disable_recursion_pending();
            continue;
        }
        if (p.extension() == ".lua" && it->is_regular_file(ec))
            files.push_back(p.lexically_relative(dir).generic_string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// ---- Running one scene ------------------------------------------------------------------------

/// The options every child gets besides the scene: --quiet --stats --threads 1 and the
/// per-scene options the TA gave, with paths made absolute (the child runs elsewhere).
std::vector<std::string> childOptions(const CommandLine& cl) {
    std::vector<std::string> args = {"--quiet", "--stats", "--threads", "1"};
    if (cl.features != "all") args.push_back("--features=" + cl.features);
    if (cl.legacy) args.push_back("--legacy");
    if (cl.modern) args.push_back("--modern");
    if (cl.lenient) args.push_back("--lenient");
    if (cl.unsafeLua) args.push_back("--unsafe-lua");
    for (const std::string& d : cl.dialects) {
        args.push_back("--dialect");
        args.push_back(fs::absolute(d).lexically_normal().string());
    }
    for (const std::string& d : cl.assetDirs) {
        args.push_back("--assets");
        args.push_back(fs::absolute(d).lexically_normal().string());
    }
    if (cl.width > 0)
        args.push_back("--size=" + std::to_string(cl.width) + "x" + std::to_string(cl.height));
    if (cl.samplesPerPixel > 0) args.push_back("--spp=" + std::to_string(cl.samplesPerPixel));
    if (cl.seed != 0) args.push_back("--seed=" + std::to_string(cl.seed));
    if (cl.maxDepth >= 0) args.push_back("--max-depth=" + std::to_string(cl.maxDepth));
    if (cl.targetError > 0) {
        char error[32];
        // 15 digits give back any target typed with 15 or fewer, and read as typed.
        std::snprintf(error, sizeof error, "%.15g", cl.targetError);
        args.push_back(std::string("--target-error=") + error);
    }
    if (cl.minSpp > 0) args.push_back("--min-spp=" + std::to_string(cl.minSpp));
    if (cl.maxSpp > 0) args.push_back("--max-spp=" + std::to_string(cl.maxSpp));
    if (cl.aovSampleCount) args.push_back("--aov=sample-count");
    // Each scene gets the memory limit asked for; by default each takes the machine's share.
    if (cl.memory.origin.rfind("--max-memory", 0) == 0)
        args.push_back("--max-memory=" + std::to_string(cl.memory.limit));
    for (const auto& [name, value] : cl.featureOptions) args.push_back("--" + name + "=" + value);
    return args;
}

/// Everything one child needs, prepared before fork so that the child itself calls only
/// async-signal-safe functions.
struct ChildPlan {
    std::string exe;  ///< This binary.
    std::vector<std::string> argv;
    std::string folder;  ///< The scene's folder: the child's working directory.
    std::string stdoutPath, stderrPath;
};

/// In the child: point file descriptor `fd` at `path` (opened with `flags`).
void redirect(int fd, const char* path, int flags) {
    const int f = open(path, flags | O_CLOEXEC, 0644);
    if (f >= 0) dup2(f, fd);
}

/// Start one child in its own process group; returns its pid, or -1 if fork failed.
pid_t spawnChild(const ChildPlan& plan) {
    std::vector<char*> argv;
    for (const std::string& a : plan.argv) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid != 0) {
        // The parent sets the group too, so a kill right after fork cannot miss it.
        if (pid > 0) setpgid(pid, pid);
        return pid;
    }
    // The child: its own process group (so a kill reaches anything it starts), killed with
    // the batch, stdin from /dev/null, stdout and stderr into the logs, in the scene's folder.
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    redirect(STDIN_FILENO, "/dev/null", O_RDONLY);
    redirect(STDOUT_FILENO, plan.stdoutPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC);
    redirect(STDERR_FILENO, plan.stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC);
    if (chdir(plan.folder.c_str()) == 0) execv(plan.exe.c_str(), argv.data());
    const char message[] = "rt: error: --batch could not start rt in the scene's folder\n";
    [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, message, sizeof message - 1);
    _exit(127);
}

/// The number after `key` in `line` (e.g. "render " in "build 0.1 s, render 0.2 s"), or -1.
double numberAfter(const std::string& line, const std::string& key) {
    const size_t at = line.find(key);
    if (at == std::string::npos) return -1;
    return std::strtod(line.c_str() + at + key.size(), nullptr);
}

/// The rest of `line` after `prefix`, or false if it does not start with it.
bool afterPrefix(const std::string& line, const std::string& prefix, std::string* rest) {
    if (!line.starts_with(prefix)) return false;
    *rest = line.substr(prefix.size());
    return true;
}

/// Sort a child's stderr into the result: messages by kind, and from the --stats blocks the
/// images written, the render time and the rays. Returns the images' paths as rt printed them.
std::vector<std::string> readStderr(const std::string& text, SceneResult* result) {
    std::vector<std::string> images;
    std::istringstream in(text);
    std::string line, rest;
    bool inStats = false;    // the indented lines after "stats for FILE"
    bool inLenient = false;  // the list after "rt: --lenient ignored ..."
    while (std::getline(in, line)) {
        if (afterPrefix(line, "stats for ", &rest)) {
            images.push_back(rest);
            result->haveStats = inStats = true;
        } else if (inStats && line.starts_with("  ")) {
            if (line.find("(total ") != std::string::npos)
                result->rays += std::strtoull(line.c_str() + line.find("(total ") + 7, nullptr, 10);
            if (afterPrefix(line, "  era", &rest) && result->era.empty())
                result->era = rest.substr(std::min(rest.size(), rest.find_first_not_of(' ')));
            if (line.starts_with("  time") && numberAfter(line, "render ") >= 0)
                result->renderSeconds += numberAfter(line, "render ");
        } else if (inLenient && afterPrefix(line, "rt:   ", &rest)) {
            result->standIns.push_back(rest);
        } else {
            inStats = inLenient = false;
            if (line.starts_with("rt: --lenient ignored "))
                inLenient = true;  // its list follows
            else if (afterPrefix(line, "rt: error: ", &rest))
                result->errors.push_back(rest);
            else if (afterPrefix(line, "rt: warning: ", &rest))
                result->warnings.push_back(rest);
            else if (!line.empty())
                result->other.push_back(line);
        }
    }
    return images;
}

/// Width and height from a PNG's header, or false if the file is not a readable PNG.
bool pngSize(const fs::path& file, int* width, int* height) {
    unsigned char header[24] = {};
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return false;
    if (std::memcmp(header, "\x89PNG\r\n\x1a\n", 8) != 0) return false;
    auto be32 = [&](int at) {
        return static_cast<int>((header[at] << 24) | (header[at + 1] << 16) |
                                (header[at + 2] << 8) | header[at + 3]);
    };
    *width = be32(16);
    *height = be32(20);
    return true;
}

/// A short description of how a child ended, and the status it gives the scene.
Status exitStatus(int waitStatus, bool killed, double limit, std::string* note) {
    if (killed) {
        *note = "stopped after the time limit of " + std::to_string(static_cast<int>(limit)) +
                " s (--scene-time-limit)";
        return Status::TimedOut;
    }
    if (WIFSIGNALED(waitStatus)) {
        const int sig = WTERMSIG(waitStatus);
        *note = "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
        return Status::Crashed;
    }
    const int code = WIFEXITED(waitStatus) ? WEXITSTATUS(waitStatus) : -1;
    if (code == 0) return Status::Ok;
    if (code != 1) *note = "exit code " + std::to_string(code);
    return Status::Error;
}

/// Pixels as 8-bit RGB, freed with stbi_image_free.
using Pixels = std::unique_ptr<unsigned char, void (*)(void*)>;

/// How raybook's render compares with the student's own image: "RMSE 0.0123 ..." over every
/// channel in [0, 1], or why the two cannot be compared.
std::string compareWithOwn(const fs::path& render, const fs::path& own) {
    int w[2] = {}, h[2] = {}, channels = 0;
    Pixels a(stbi_load(render.c_str(), &w[0], &h[0], &channels, 3), stbi_image_free);
    Pixels b(stbi_load(own.c_str(), &w[1], &h[1], &channels, 3), stbi_image_free);
    if (!a) return "raybook's render could not be read back";
    if (!b) return "not compared: the student's file is not an image stb_image can read";
    if (w[0] != w[1] || h[0] != h[1])
        return "not compared: the sizes differ (" + std::to_string(w[0]) + "x" +
               std::to_string(h[0]) + " rendered, " + std::to_string(w[1]) + "x" +
               std::to_string(h[1]) + " the student's)";
    // RMSE over every channel of every pixel, in [0, 1] (1 = black against white everywhere).
    const size_t n = static_cast<size_t>(w[0]) * static_cast<size_t>(h[0]) * 3;
    double sum = 0;
    size_t differing = 0;
    for (size_t i = 0; i < n; ++i) {
        const double d = (a.get()[i] - b.get()[i]) / 255.0;
        sum += d * d;
        differing += a.get()[i] != b.get()[i];
    }
    char text[160];
    std::snprintf(text, sizeof text,
                  "RMSE %.4f against the student's image (%.1f%% of values differ)",
                  std::sqrt(sum / static_cast<double>(n)),
                  100.0 * static_cast<double>(differing) / static_cast<double>(n));
    return text;
}

/// Fill in a finished scene's result from its exit and its logs.
void finishScene(const fs::path& dir, int waitStatus, bool killed, double limit,
                 SceneResult* result) {
    result->status = exitStatus(waitStatus, killed, limit, &result->note);
    const fs::path folder = (dir / result->path).parent_path();
    const fs::path renders = dir / result->renders;
    for (const std::string& written : readStderr(readFile(dir / result->stderrLog), result)) {
        // rt prints each image where --output-dir put it: under the scene's renders folder, at
        // the path the scene named relative to its own folder.
        const fs::path file = (folder / written).lexically_normal();
        ImageInfo image;
        image.path = file.lexically_relative(dir).generic_string();
        image.exists = fs::is_regular_file(file);
        if (image.exists) pngSize(file, &image.width, &image.height);
        // The student's own image of that name, beside the scene, is left as it is and compared.
        const fs::path own = (folder / file.lexically_relative(renders)).lexically_normal();
        if (image.exists && fs::is_regular_file(own)) {
            image.own = own.lexically_relative(dir).generic_string();
            image.comparison = compareWithOwn(file, own);
        }
        result->images.push_back(image);
    }
    if (result->status == Status::Ok && result->images.empty())
        result->note = "finished without writing an image";
}

// ---- Scheduling -------------------------------------------------------------------------------

/// How many children run at once: --threads if given, else the number of cores.
int jobCount(const CommandLine& cl, size_t scenes) {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int jobs = cl.threads > 0 ? cl.threads : cores;
    return std::max(1, std::min(jobs, static_cast<int>(scenes)));
}

/// "with 3 stand-ins (--lenient)" for a scene that needed them, else "".
std::string standInNote(const SceneResult& r) {
    const size_t n = r.standIns.size();
    if (n == 0) return "";
    return "with " + std::to_string(n) + " stand-in" + (n == 1 ? "" : "s") + " (--lenient)";
}

/// One stdout line for a finished scene: status, wall time, path, and its first error (for a
/// scene rendered with stand-ins, how many).
void printSceneLine(const SceneResult& r) {
    std::string why = !r.errors.empty() ? r.errors.front() : r.note;
    if (r.status == Status::Ok) why = standInNote(r);
    if (r.status == Status::Helper) why = "never calls gr.render";
    if (why.size() > 110) why = why.substr(0, 107) + "...";
    char time[32] = "      -  ";
    if (r.status != Status::Helper) std::snprintf(time, sizeof time, "%7.2f s", r.wallSeconds);
    std::printf("%-14s %s  %s%s%s\n", statusWord(r.status), time, r.path.c_str(),
                why.empty() ? "" : "  -- ", why.c_str());
    std::fflush(stdout);
}

/// The path of this binary, for the children.
std::string selfExecutable(char** argv) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) return self.string();
    return fs::absolute(argv[0]).string();
}

/// Fill in a scene's result from how its child ended, and print its line unless `quiet`.
void applyEnd(const fs::path& dir, double limit, bool quiet, const ChildEnd& end,
              std::vector<SceneResult>* results) {
    SceneResult& r = (*results)[end.index];
    if (end.started) {
        r.wallSeconds = end.wallSeconds;
        finishScene(dir, end.waitStatus, end.killed, limit, &r);
    } else {
        r.status = Status::Error;
        r.note = end.note;
    }
    if (!quiet) printSceneLine(r);
}

/// Run the scenes of `results` at the indices in `queue`, `jobs` at a time, each killed after
/// `limit` seconds; fills in each result as its child ends, and returns how each ended.
std::vector<ChildEnd> runScenes(const fs::path& dir, const std::string& exe,
                                const std::vector<std::string>& options,
                                const std::vector<size_t>& queue, int jobs, double limit,
                                bool quiet, std::vector<SceneResult>* results) {
    std::vector<ChildEnd> ends;
    std::vector<RunningChild> running;
    size_t next = 0;
    while (next < queue.size() || !running.empty()) {
        // Step 1: start children until `jobs` run.
        while (next < queue.size() && static_cast<int>(running.size()) < jobs) {
            SceneResult& r = (*results)[queue[next++]];
            const fs::path scene = dir / r.path;
            ChildPlan plan;
            plan.exe = exe;
            plan.argv = {exe};
            plan.argv.insert(plan.argv.end(), options.begin(), options.end());
            plan.argv.push_back("--output-dir");
            plan.argv.push_back((dir / r.renders).string());
            plan.argv.push_back(scene.filename().string());
            plan.folder = scene.parent_path().string();
            plan.stdoutPath = (dir / r.stdoutLog).string();
            plan.stderrPath = (dir / r.stderrLog).string();
            fs::create_directories((dir / r.stderrLog).parent_path());
            const pid_t pid = spawnChild(plan);
            if (pid < 0) {
                ChildEnd end;
                end.index = static_cast<size_t>(&r - results->data());
                end.started = false;
                end.note = std::string("could not start a child: ") + std::strerror(errno);
                applyEnd(dir, limit, quiet, end, results);
                ends.push_back(end);
                continue;
            }
            running.push_back({pid, static_cast<size_t>(&r - results->data()), Clock::now()});
        }
        // Step 2: reap the children that ended, and kill those past the time limit.
        bool changed = false;
        for (size_t k = 0; k < running.size();) {
            RunningChild& c = running[k];
            const double seconds = std::chrono::duration<double>(Clock::now() - c.start).count();
            int status = 0;
            if (waitpid(c.pid, &status, WNOHANG) == c.pid) {
                const ChildEnd end{c.index, true, status, c.killed, seconds, ""};
                applyEnd(dir, limit, quiet, end, results);
                ends.push_back(end);
                running.erase(running.begin() + static_cast<long>(k));
                changed = true;
                continue;
            }
            if (!c.killed && seconds > limit) {
                kill(-c.pid, SIGKILL);
                kill(c.pid, SIGKILL);
                c.killed = true;
            }
            ++k;
        }
        // Step 3: wait a little before looking again.
        if (!changed) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return ends;
}

/// `ends` as bytes, for rank 0.
std::vector<std::byte> packEnds(const std::vector<ChildEnd>& ends) {
    std::vector<std::byte> bytes;
    auto put = [&](const void* p, size_t n) {
        bytes.insert(bytes.end(), static_cast<const std::byte*>(p),
                     static_cast<const std::byte*>(p) + n);
    };
    for (const ChildEnd& e : ends) {
        const std::uint64_t index = e.index, noteSize = e.note.size();
        const std::int32_t status = e.waitStatus;
        const std::uint8_t flags = (e.started ? 1 : 0) | (e.killed ? 2 : 0);
        put(&index, 8);
        put(&status, 4);
        put(&flags, 1);
        put(&e.wallSeconds, 8);
        put(&noteSize, 8);
        put(e.note.data(), e.note.size());
    }
    return bytes;
}

/// The ChildEnds packEnds wrote.
std::vector<ChildEnd> unpackEnds(const std::vector<std::byte>& bytes) {
    std::vector<ChildEnd> ends;
    size_t at = 0;
    auto get = [&](void* p, size_t n) {
        std::memcpy(p, bytes.data() + at, n);
        at += n;
    };
    while (at < bytes.size()) {
        ChildEnd e;
        std::uint64_t index = 0, noteSize = 0;
        std::int32_t status = 0;
        std::uint8_t flags = 0;
        get(&index, 8);
        get(&status, 4);
        get(&flags, 1);
        get(&e.wallSeconds, 8);
        get(&noteSize, 8);
        e.note.resize(noteSize);
        get(e.note.data(), noteSize);
        e.index = index;
        e.waitStatus = status;
        e.started = flags & 1;
        e.killed = flags & 2;
        ends.push_back(std::move(e));
    }
    return ends;
}

// ---- The report -------------------------------------------------------------------------------

/// A relative '/'-separated path as a URL path: every byte but [A-Za-z0-9-._~/] escaped.
std::string urlPath(const std::string& path) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (const unsigned char c : path) {
        if (std::isalnum(c) || std::strchr("-._~/", c)) {
            out += static_cast<char>(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

/// A count with thousands separators: 1234567 -> "1,234,567".
std::string withCommas(unsigned long long n) {
    std::string digits = std::to_string(n), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

/// Seconds with two decimals: "0.42 s".
std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", s);
    return text;
}

/// The page's style sheet: inline, so the report is one self-contained file.
const char* reportCss() {
    return R"(
:root { --ok: #1a7f37; --error: #cf222e; --timeout: #9a6700; --crash: #8250df; --helper: #6e7781; }
* { box-sizing: border-box; }
body { font: 14px/1.45 system-ui, -apple-system, "Segoe UI", sans-serif; color: #1f2328;
       background: #f6f8fa; margin: 0; padding: 24px; }
main { max-width: 1100px; margin: 0 auto; }
h1 { font-size: 22px; margin: 0 0 4px; }
.sub { color: #57606a; margin: 0 0 16px; }
code, .mono { font-family: ui-monospace, "SFMono-Regular", Menlo, Consolas, monospace; font-size: 12.5px; }
.counts { display: flex; flex-wrap: wrap; gap: 8px; margin: 12px 0; }
.count { border-radius: 6px; padding: 6px 12px; color: #fff; font-weight: 600; }
.count.zero { opacity: 0.35; }
.ok { --c: var(--ok); } .error { --c: var(--error); } .timeout { --c: var(--timeout); }
.crash { --c: var(--crash); } .helper { --c: var(--helper); }
.count, .badge { background: var(--c); }
.attention { background: #fff; border: 1px solid #d0d7de; border-radius: 6px; padding: 8px 12px;
             margin: 12px 0 20px; }
.attention a { margin-right: 12px; }
.scene { display: grid; grid-template-columns: 340px 1fr; gap: 16px; background: #fff;
         border: 1px solid #d0d7de; border-left: 6px solid var(--c); border-radius: 6px;
         padding: 12px; margin: 0 0 10px; }
.thumbs { display: flex; flex-wrap: wrap; gap: 6px; align-content: flex-start; }
.thumbs figure { margin: 0; }
.thumbs img { display: block; max-width: 160px; max-height: 120px; background: #000;
              border: 1px solid #d0d7de; }
.thumbs figcaption { font-size: 11px; color: #57606a; max-width: 160px; overflow-wrap: anywhere; }
.noimage { width: 160px; height: 56px; display: flex; align-items: center; justify-content: center;
           background: repeating-linear-gradient(45deg, #f6f8fa, #f6f8fa 8px, #eaeef2 8px, #eaeef2 16px);
           color: #57606a; border: 1px dashed #d0d7de; font-size: 12px; text-align: center; }
.head { display: flex; align-items: baseline; gap: 10px; flex-wrap: wrap; }
.path { font-weight: 600; font-size: 15px; overflow-wrap: anywhere; }
.badge { color: #fff; border-radius: 10px; padding: 1px 9px; font-size: 12px; font-weight: 600; }
.meta { color: #57606a; margin: 2px 0; }
.era { margin: 4px 0; color: #57606a; font-size: 13px; }
.era strong { color: #0550ae; }
.badge.warn { background: #d4a72c; }
ul.msgs { margin: 6px 0; padding-left: 0; list-style: none; }
ul.msgs li { padding: 3px 8px; margin: 2px 0; border-radius: 4px; overflow-wrap: anywhere;
             white-space: pre-wrap; }
ul.errors li { background: #ffebe9; color: #82071e; }
ul.warnings li { background: #fff8c5; color: #4d2d00; }
ul.compare li { background: #ddf4ff; color: #0a3069; }
ul.standins li { background: #fbefff; color: #6e1a74; }
.badge.standin { background: #bf3989; }
.thumbs figure.own img { border: 2px solid #0969da; }
.note { font-style: italic; color: #57606a; }
details { margin-top: 4px; color: #57606a; }
details pre { white-space: pre-wrap; margin: 4px 0; }
.links a { color: #0969da; margin-right: 10px; font-size: 12px; }
footer { color: #57606a; font-size: 12px; margin-top: 20px; }
)";
}

/// The thumbnails of a scene's images, or a placeholder saying why there is none.
std::string thumbnails(const SceneResult& r) {
    std::string html;
    for (const ImageInfo& image : r.images) {
        if (!image.exists) continue;
        const std::string url = escapeHtml(urlPath(image.path));
        std::string caption =
            (image.own.empty() ? "" : "raybook's ") + fs::path(image.path).filename().string();
        if (image.width > 0)
            caption +=
                " (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")";
        html += "<figure><a href=\"" + url + "\"><img src=\"" + url + "\" alt=\"" +
                escapeHtml(image.path) + "\" loading=\"lazy\"></a><figcaption>" +
                escapeHtml(caption) + "</figcaption></figure>";
        if (image.own.empty()) continue;
        // The student's own image of the same name, as they handed it in.
        const std::string own = escapeHtml(urlPath(image.own));
        html += "<figure class=\"own\"><a href=\"" + own + "\"><img src=\"" + own + "\" alt=\"" +
                escapeHtml(image.own) + "\" loading=\"lazy\"></a><figcaption>student's " +
                escapeHtml(fs::path(image.own).filename().string()) + "</figcaption></figure>";
    }
    if (html.empty()) {
        const char* why = r.status == Status::Helper ? "helper: nothing to render" : "no image";
        html = std::string("<div class=\"noimage\">") + why + "</div>";
    }
    return "<div class=\"thumbs\">" + html + "</div>";
}

/// A list of messages of one kind (errors, warnings or stand-ins), escaped; empty if none.
std::string messageList(const std::vector<std::string>& messages, const char* kind) {
    if (messages.empty()) return "";
    std::string html = std::string("<ul class=\"msgs ") + kind + "\">";
    for (const std::string& m : messages) html += "<li class=\"mono\">" + escapeHtml(m) + "</li>";
    return html + "</ul>";
}

/// The line of numbers under a scene's path: wall time, render time, rays, images.
std::string metaLine(const SceneResult& r) {
    if (r.status == Status::Helper) return "never calls gr.render: a module for other scenes";
    std::string line = seconds(r.wallSeconds) + " in all";
    if (r.haveStats)
        line += " &middot; render " + seconds(r.renderSeconds) + " &middot; " + withCommas(r.rays) +
                " rays";
    const size_t n = r.images.size();
    line += " &middot; " + std::to_string(n) + (n == 1 ? " image" : " images");
    return line;
}

/// Notes about images: missing after the batch.
std::vector<std::string> imageNotes(const SceneResult& r) {
    std::vector<std::string> notes;
    for (const ImageInfo& image : r.images)
        if (!image.exists) notes.push_back(image.path + " was written but is gone");
    return notes;
}

/// The comparisons of raybook's renders with the student's own images, one line each.
std::string comparisonList(const SceneResult& r) {
    std::string html;
    for (const ImageInfo& image : r.images)
        if (!image.own.empty())
            html += "<li class=\"mono\">" + escapeHtml(image.own) + ": " +
                    escapeHtml(image.comparison) + "</li>";
    return html.empty() ? "" : "<ul class=\"msgs compare\">" + html + "</ul>";
}

/// The era line: the era itself in bold ("current framework (...)"), then the evidence.
std::string eraLine(const std::string& era) {
    const size_t close = era.find(')');
    const size_t cut = close == std::string::npos ? era.size() : close + 1;
    return "<div class=\"era\">era: <strong>" + escapeHtml(era.substr(0, cut)) + "</strong>" +
           escapeHtml(era.substr(cut)) + "</div>";
}

/// One scene's card: thumbnails on the left; path, status, era, numbers, messages on the right.
std::string sceneCard(const SceneResult& r) {
    std::string html = std::string("<section class=\"scene ") + statusClass(r.status) + "\" id=\"" +
                       escapeHtml(urlPath(r.path)) + "\" data-path=\"" + escapeHtml(r.path) +
                       "\" data-status=\"" + statusWord(r.status) + "\" data-stand-ins=\"" +
                       std::to_string(r.standIns.size()) + "\">";
    html += thumbnails(r) + "<div>";
    html += "<div class=\"head\"><span class=\"path mono\">" + escapeHtml(r.path) +
            "</span><span class=\"badge\">" + statusWord(r.status) + "</span>";
    std::vector<std::string> warnings = r.warnings;
    for (const std::string& n : imageNotes(r)) warnings.push_back(n);
    if (!warnings.empty())
        html += "<span class=\"badge warn\">" + std::to_string(warnings.size()) +
                (warnings.size() == 1 ? " warning" : " warnings") + "</span>";
    if (!r.standIns.empty())
        html += "<span class=\"badge standin\">" + std::to_string(r.standIns.size()) +
                (r.standIns.size() == 1 ? " stand-in" : " stand-ins") + "</span>";
    html += "</div>";
    if (!r.era.empty()) html += eraLine(r.era);
    html += "<div class=\"meta\">" + metaLine(r) + "</div>";
    if (!r.note.empty()) html += "<div class=\"note\">" + escapeHtml(r.note) + "</div>";
    html += messageList(r.errors, "errors");
    html += messageList(warnings, "warnings");
    html += messageList(r.standIns, "standins");
    html += comparisonList(r);
    if (!r.other.empty()) {
        std::string text;
        for (const std::string& line : r.other) text += line + "\n";
        html += "<details><summary>other output (" + std::to_string(r.other.size()) +
                " lines)</summary><pre class=\"mono\">" + escapeHtml(text) + "</pre></details>";
    }
    html += "<div class=\"links\"><a href=\"" + escapeHtml(urlPath(r.path)) + "\">scene</a>";
    if (r.status != Status::Helper)
        html += "<a href=\"" + escapeHtml(urlPath(r.stderrLog)) + "\">stderr</a><a href=\"" +
                escapeHtml(urlPath(r.stdoutLog)) + "\">stdout</a>";
    return html + "</div></div></section>\n";
}

/// The count of scenes with status `s`.
size_t countOf(const std::vector<SceneResult>& results, Status s) {
    return static_cast<size_t>(std::count_if(results.begin(), results.end(),
                                             [&](const SceneResult& r) { return r.status == s; }));
}

/// The summary at the top: one coloured count per status, links to the scenes that need a
/// look (every status but ok and helper), and links to those that rendered with stand-ins
/// (--lenient), whose images are not wholly the student's.
std::string summary(const std::vector<SceneResult>& results) {
    std::string html = "<div class=\"counts\">";
    for (const Status s :
         {Status::Ok, Status::Error, Status::TimedOut, Status::Crashed, Status::Helper}) {
        const size_t n = countOf(results, s);
        html += std::string("<span class=\"count ") + statusClass(s) + (n == 0 ? " zero" : "") +
                "\">" + std::to_string(n) + " " + statusWord(s) + "</span>";
    }
    html += "</div>";
    std::string attention;
    for (const SceneResult& r : results)
        if (r.status != Status::Ok && r.status != Status::Helper)
            attention += "<a class=\"mono\" href=\"#" + escapeHtml(urlPath(r.path)) + "\">" +
                         escapeHtml(r.path) + "</a>";
    if (!attention.empty())
        html += "<div class=\"attention\"><strong>Needs a look:</strong> " + attention + "</div>";
    std::string standIns;
    for (const SceneResult& r : results)
        if (!r.standIns.empty())
            standIns += "<a class=\"mono\" href=\"#" + escapeHtml(urlPath(r.path)) + "\">" +
                        escapeHtml(r.path) + "</a>";
    if (!standIns.empty())
        html +=
            "<div class=\"attention standins\"><strong>Needed stand-ins (--lenient):</strong> " +
            standIns + "</div>";
    return html;
}

/// Write DIR/raybook-report.html.
void writeReport(const fs::path& file, const std::vector<SceneResult>& results,
                 const BatchInfo& info) {
    const size_t helpers = countOf(results, Status::Helper);
    const size_t scenes = results.size() - helpers;
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">" +
                       std::string(kReportGenerator) +
                       "<title>raybook batch: " + escapeHtml(info.dir.filename().string()) +
                       "</title><style>" + reportCss() + "</style></head><body><main>\n";
    html += "<h1>raybook batch report: " + escapeHtml(info.dir.filename().string()) + "</h1>";
    html += "<p class=\"sub\"><span class=\"mono\">" + escapeHtml(info.dir.string()) +
            "</span><br>" + std::to_string(scenes) + " scenes and " + std::to_string(helpers) +
            " helpers, rendered " + escapeHtml(info.startedAt) + " in " +
            seconds(info.totalSeconds) + " with " + std::to_string(info.jobs) +
            " at a time, at most " + std::to_string(static_cast<int>(info.timeLimit)) +
            " s each<br>each scene ran as <span class=\"mono\">rt " +
            escapeHtml(info.passedOptions) + " SCENE.lua</span> in its own folder</p>\n";
    html += summary(results) + "\n";
    for (const SceneResult& r : results) html += sceneCard(r);
    html += "<footer>Full logs and raybook's renders: <span class=\"mono\">" +
            std::string(kReportFolder) +
            "/SCENE.lua/</span>. The batch writes nothing else; a student's own image of the "
            "name a scene renders is shown beside raybook's, as it was handed in (blue "
            "frame).</footer>\n</main></body></html>\n";
    std::ofstream out(file, std::ios::binary);
    out << html;
    if (!out) throw InputError("--batch: cannot write " + file.string());
}

/// True when the report page at `page` was written by rt --batch (an older rt wrote no
/// generator line, only its title).
bool isBatchReport(const fs::path& page) {
    const std::string text = readFile(page);
    return text.find(kReportGenerator) != std::string::npos ||
           text.find("<title>raybook batch: ") != std::string::npos;
}

/// Empty the report folder for a new batch, refusing a folder or page the batch did not make,
/// and stamp the folder as the batch's.
void prepareReportFolder(const fs::path& dir) {
    const fs::path folder = dir / kReportFolder;
    const fs::path page = dir / kReportPage;
    std::error_code ec;
    const bool pageExists = fs::exists(page, ec);
    if (pageExists && !isBatchReport(page))
        throw InputError("--batch: " + page.string() +
                         " exists but was not written by rt --batch; move it away or delete it");
    // A folder with the stamp is the batch's; so is one beside a report page (an older rt's).
    if (fs::exists(folder, ec) && !fs::exists(folder / kReportStamp, ec) && !pageExists)
        throw InputError("--batch: " + folder.string() +
                         " exists but was not made by rt --batch (it has no " + kReportStamp +
                         " file); the batch writes its renders and logs there, so move the folder "
                         "away or delete it");
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / kReportStamp)
        << "This folder is rt --batch's: the next batch over its parent empties it.\n";
}

/// The local date and time, for the report.
std::string now() {
    const std::time_t t = std::time(nullptr);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", std::localtime(&t));
    return text;
}

/// The options as one line, for the report.
std::string joined(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) line += (line.empty() ? "" : " ") + w;
    return line;
}

}  // namespace

int runBatch(const CommandLine& cl, int, char** argv, Cluster& cluster) {
    const auto t0 = Clock::now();
    // Step 1: check DIR and the options that make no sense for a batch.
    std::error_code ec;
    if (!fs::is_directory(cl.batchDir, ec))
        throw InputError("--batch: '" + cl.batchDir + "' is not a folder");
    if (!cl.output.empty())
        throw InputError("--batch: --output names one image; each scene writes its own");
    if (!cl.outputDir.empty())
        throw InputError(
            "--batch: --output-dir is the batch's own choice: each scene's renders "
            "go to DIR/raybook-report/SCENE.lua/");
    BatchInfo info;
    info.dir = fs::absolute(cl.batchDir).lexically_normal();
    if (info.dir.filename().empty()) info.dir = info.dir.parent_path();

    // Step 2: find the scenes; set the helpers aside.
    std::vector<SceneResult> results;
    for (const std::string& path : findLuaFiles(info.dir)) {
        SceneResult r;
        r.path = path;
        r.status = isHelper(info.dir / path) ? Status::Helper : Status::Ok;
        r.stdoutLog = std::string(kReportFolder) + "/" + path + ".stdout.txt";
        r.stderrLog = std::string(kReportFolder) + "/" + path + ".stderr.txt";
        r.renders = std::string(kReportFolder) + "/" + path;
        results.push_back(r);
    }
    const size_t helpers = countOf(results, Status::Helper);
    if (results.size() == helpers)
        throw InputError("--batch: no scenes under '" + cl.batchDir + "' (no .lua file" +
                         (helpers ? " that calls gr.render" : "") + ")");

    // Step 3: run the scenes; the report folder starts empty each time (rank 0 empties it
    // before any rank starts).
    std::exception_ptr failure;
    try {
        if (cluster.writesOutput()) prepareReportFolder(info.dir);
    } catch (...) {
        failure = std::current_exception();
    }
    cluster.agree(failure);
    const std::vector<std::string> options = childOptions(cl);
    info.jobs = jobCount(cl, results.size() - helpers);
    info.timeLimit = cl.sceneTimeLimit;
    info.passedOptions = joined(options);
    info.startedAt = now();
    if (!cl.quiet) {
        std::printf("rendering %zu scenes under %s, %d at a time%s, at most %d s each\n",
                    results.size() - helpers, info.dir.c_str(), info.jobs,
                    cluster.size() > 1
                        ? (" on each of " + std::to_string(cluster.size()) + " ranks").c_str()
                        : "",
                    static_cast<int>(info.timeLimit));
        for (const SceneResult& r : results)
            if (r.status == Status::Helper) printSceneLine(r);
    }
    // Under MPI each rank runs every size-th scene; rank 0 hears how the others' ended.
    std::vector<size_t> mine;
    for (size_t i = 0, k = 0; i < results.size(); ++i)
        if (results[i].status != Status::Helper &&
            static_cast<int>(k++ % static_cast<size_t>(cluster.size())) == cluster.rank())
            mine.push_back(i);
    const std::vector<ChildEnd> ends = runScenes(info.dir, selfExecutable(argv), options, mine,
                                                 info.jobs, info.timeLimit, cl.quiet, &results);
    if (cluster.size() > 1) {
        const auto parts = cluster.gatherToFirst(packEnds(ends));
        for (size_t rank = 1; rank < parts.size(); ++rank)
            for (const ChildEnd& end : unpackEnds(parts[rank]))
                applyEnd(info.dir, info.timeLimit, cl.quiet, end, &results);
    }
    if (!cluster.writesOutput()) return 0;

    // Step 4: the report, and the summary line.
    info.totalSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    const fs::path report = info.dir / kReportPage;
    writeReport(report, results, info);
    const size_t failed = countOf(results, Status::Error) + countOf(results, Status::Crashed);
    std::printf("%zu rendered, %zu failed, %zu timed out\n", countOf(results, Status::Ok), failed,
                countOf(results, Status::TimedOut));
    std::printf("report: %s (%.1f s)\n", report.c_str(), info.totalSeconds);
    return 0;
}

}  // namespace rb
