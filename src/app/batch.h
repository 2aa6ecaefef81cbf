/// \file
/// Batch mode: render every scene under a folder, as a TA renders a class, with a report.
#pragma once

#include "app/options.h"
#include "core/cluster.h"

namespace rb {

/// Render every scene under cl.batchDir, each by a child rt process run in the scene's own
/// folder with a time limit, and write DIR/raybook-report.html. Returns rt's exit code. Under
/// MPI the scenes are dealt round-robin over the ranks (DIR on a shared file system), and
/// rank 0 writes the report from every rank's results.
int runBatch(const CommandLine& cl, int argc, char** argv, Cluster& cluster);

}  // namespace rb
