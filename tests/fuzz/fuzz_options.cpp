/// \file
/// Fuzz target: the command line of ./rt (src/core/options.cpp). The input is the argument
/// list, one argument per line ('\n' separates them; an argument may hold any other byte).
/// After parsing, the same checks ./rt makes before a render: the --features list, --size and
/// the chapters' --name=value options (checked when each feature installs itself into an
/// empty scene).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/options.h"
#include "core/error.h"
#include "core/image.h"
#include "core/world.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::vector<rb::Feature> built = rb::builtFeatures();
    // Split the input into arguments; argv[0] is the program's name.
    std::vector<std::string> args = {"rt"};
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::size_t start = 0;
    while (start <= text.size() && size > 0) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        args.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    argv.push_back(nullptr);
    try {
        const rb::CommandLine cl =
            rb::parseCommandLine(static_cast<int>(args.size()), argv.data(), built);
        if (cl.help) rb::usage(built);
        const rb::FeatureSet features(built, cl.features);
        if (cl.width > 0) rb::checkImageSize(cl.width, cl.height, "--size: ");
        rb::buildWorld(rb::LoadedRender{}, features, cl.featureOptions, cl.maxDepth);
    } catch (const rb::InputError&) {
        // Bad input, reported as it should be.
    }
    return 0;
}
