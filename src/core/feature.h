/// \file
/// Features: each chapter registers itself here, and `--features` switches them on and off.
#pragma once

#include <string>
#include <vector>

namespace rb {

struct Pipeline;
struct RenderContext;
struct Scene;
class LuaBindings;

/// A command-line option a feature adds, e.g. {"fresnel", "schlick|exact", "Fresnel formula"}.
struct FeatureOption {
    const char* name;          ///< Written --name=value.
    const char* value;         ///< What the value looks like, for --help.
    const char* help;          ///< One line for --help.
    const char* defaultValue;  ///< What applies when the option is absent, for --help.
};

class Image;
struct Warp;

/// An image file format a feature can write, chosen by the output name's extension
/// (e.g. {".hdr", "a Radiance HDR image", writeHdr}).
struct OutputFormat {
    const char* extension;    ///< Lower case, with the dot.
    const char* description;  ///< For messages: "a Radiance HDR image".
    /// Write the film (linear radiance) to `path` atomically; throws InputError naming the path.
    void (*write)(const Image& film, const std::string& path);
};

/// One chapter's module as the core sees it.
struct Feature {
    const char* name;   ///< Switch name, e.g. "reflection".
    int chapter;        ///< Chapter number.
    const char* title;  ///< One line for --list-features.
    bool switchable;    ///< False for the core chapters 1–3.
    /// Add the chapter's Lua calls (always, when the chapter is built). May be null.
    void (*bindLua)(LuaBindings& lua);
    /// Plug the chapter into one render (only when the feature is on). May be null.
    /// It may adjust the pipeline and the scene's settings.
    void (*install)(Pipeline& pipeline, Scene& scene, const RenderContext& context);
    /// Command-line options the chapter adds.
    std::vector<FeatureOption> options = {};
    /// Image formats the chapter writes besides PNG (chapter 12: Radiance .hdr).
    std::vector<OutputFormat> outputFormats = {};
    /// The chapter's samplers, for the sampling lab (./rt --warptest, src/lab/). May be null.
    std::vector<Warp> (*warps)() = nullptr;
};

/// The features compiled into this binary, in chapter order. Each chapter binary defines
/// its own list (see CMakeLists.txt), so chapter N's binary holds no code of chapter N+1.
std::vector<Feature> builtFeatures();

/// Which built features are on.
class FeatureSet {
  public:
    /// Parse a --features list ("all", "reflection,refraction", "all,-glossy") against the
    /// built features. Throws InputError for an unknown name or an attempt to switch off core.
    FeatureSet(const std::vector<Feature>& built, const std::string& spec);
    /// True when the named feature is built and on.
    bool enabled(const std::string& name) const;
    /// The features that are on, in chapter order.
    const std::vector<Feature>& on() const { return on_; }
    /// Every built feature.
    const std::vector<Feature>& built() const { return built_; }

  private:
    std::vector<Feature> built_;
    std::vector<Feature> on_;
};

/// The output format of a feature in `features` whose extension `path` ends in (any case),
/// or null: rt writes PNG.
const OutputFormat* outputFormatFor(const std::vector<Feature>& features, const std::string& path);

/// The newest chapter written in this source tree (CMakeLists.txt knows it): `make chapterN`
/// exists for N up to this; later chapters are planned.
int newestChapter();

/// True when chapter N is written in this source tree (chapters may land out of order).
bool chapterWritten(int chapter);

/// What a student can do about a missing chapter: "build it with make chapterN or later" for
/// a written chapter, "chapter N is planned but not written yet" for a later one.
std::string chapterAdvice(int chapter);

/// The chapter that provides a call or feature this binary lacks, for error messages; 0 if
/// the name is unknown. `title` receives the chapter's module name.
int chapterProviding(const std::string& luaCall, std::string& title);

}  // namespace rb
