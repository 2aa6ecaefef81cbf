/// \file
/// RenderContext: what a feature sees when it plugs itself into one render.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/from_chars.h"
#include "core/instance.h"
#include "core/scene_graph.h"

namespace rb {

/// One render as features see it when they install themselves: the instances (to check which
/// materials use a feature), the scene's options and the command line's feature options.
struct RenderContext {
    const std::vector<Instance>& instances;
    const RenderJob& job;
    const std::map<std::string, std::string>& commandLine;  ///< --name=value of features.

    /// True when some instance's material, or a material its shape carries, sets parameter
    /// `name` to a non-zero value.
    bool anyMaterialUses(const std::string& name) const {
        std::vector<const Material*> parts;
        for (const Instance& i : instances) {
            if (i.material && i.material->param(name) != 0.0) return true;
            // Shapes with materials of their own (CSG operands).
            parts.clear();
            i.shape->materials(parts);
            for (const Material* m : parts)
                if (m && m->param(name) != 0.0) return true;
        }
        return false;
    }
    /// A command-line feature option as text, or fallback.
    std::string cliOption(const std::string& name, const std::string& fallback = "") const {
        auto it = commandLine.find(name);
        return it == commandLine.end() ? fallback : it->second;
    }
    /// A scene option (gr.option or seed 001's gr.render extras), or fallback.
    double sceneOption(const std::string& name, double fallback) const {
        auto it = job.options.find(name);
        return it == job.options.end() ? fallback : it->second;
    }
};

/// A number as the features' messages print it ("0.5", "16").
inline std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

/// A feature's command-line number (`--option=text`), or InputError naming the option.
inline double parseNumberOption(const std::string& option, const std::string& text) {
    double v = 0.0;
    const auto [end, ec] = rb::fromChars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
        throw InputError(option + ": expected a number, got '" + text + "'");
    return v;
}

}  // namespace rb
