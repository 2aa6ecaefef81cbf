/// \file
/// What `rt --version` prints: the version, the git commit and the chapters built in.
#pragma once

#include <string>
#include <vector>

#include "core/feature.h"

namespace rb {

/// raybook's version number, e.g. "0.7.0" (CMakeLists.txt's project version).
const char* versionNumber();
/// The git commit the binary was built from, e.g. "4ef1c83", with "-dirty" when the tree had
/// uncommitted changes, or "unknown" outside a git checkout. Generated at build time.
const char* gitCommit();
/// Two lines: "raybook 0.7.0 (commit 4ef1c83)" and "chapters 1-3: raycast, phong, bvh" ("chapter 1: raycast" for chapter 1 alone; "chapters 1-8, 10: ..." when chapter 9 is not written).
std::string versionText(const std::vector<Feature>& built);

}  // namespace rb
