/// \file
/// Density grids from NanoVDB files (chapter 17): smoke and clouds simulated or sculpted in other
/// programs (Houdini, Blender, OpenVDB's tools) and saved as sparse voxel grids.
#pragma once

#include <memory>
#include <string>

#include "core/memory_budget.h"
#include "media/density.h"

namespace rb {

/// Load float grid `gridName` of the NanoVDB file `path` as a density field, in the grid's
/// own world space (its voxel size and transform). Charges the grid's bytes to `memory`
/// (may be null: no limit) BEFORE allocating. Throws InputError with a message naming the
/// file and what was expected: missing file, not a NanoVDB file, truncated/corrupt file, no
/// grid of that name (the message lists the names it has), a grid that is not a float grid,
/// over the memory budget.
///
/// The field is the trilinear interpolation of the active voxels' values, each clamped to
/// ≥ 0 (inactive voxels count as 0); its bounds are the active voxels' box grown by one voxel.
/// Only uncompressed files are read (NanoVDB's Codec::NONE).
std::shared_ptr<const DensityField> loadVdbDensity(const std::string& path,
                                                   const std::string& gridName,
                                                   const MemoryBudget* memory);

/// loadVdbDensity on a NanoVDB file's bytes, already read; `name` names them in messages.
std::shared_ptr<const DensityField> loadVdbDensityBytes(const std::string& bytes,
                                                        const std::string& name,
                                                        const std::string& gridName,
                                                        const MemoryBudget* memory);

/// True when this build can read VDB files (NanoVDB headers found).
bool vdbSupported();

}  // namespace rb
