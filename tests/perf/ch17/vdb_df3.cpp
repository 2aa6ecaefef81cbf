// Chapter 17 against POV-Ray on the plume: raybook's VDB density as a POV-Ray density file.
//
//   ch17_vdb_df3 IN.nvdb GRID OUT.df3 OUT.inc
//
// tests/perf/ch17/media_vs_povray.sh runs it at benchmark time (into a temporary folder) for
// tests/perf/povray/chapter17-plume.pov, since POV-Ray reads no VDB file. The values are
// raybook's own: the grid is loaded by rb::loadVdbDensity and each sample is its at(p), the
// field every raybook estimator reads. Only the voxel size comes from NanoVDB's file
// directory (nanovdb::io::readGridMetaData): the DensityField interface does not give it.
//
// Where the samples go. raybook's field is the trilinear interpolation of values that sit at
// the voxels' centres (integer index coordinates, NanoVDB's convention), zero at inactive
// voxels; its bounds() is the active voxels' index box grown by one voxel on each side, whose
// faces lie on voxel centres that hold zero. This program samples at exactly those centres:
// N = extent / voxel + 1 samples per axis, from bounds().lo, so each sample is a voxel's value
// (and the border samples are 0). POV-Ray 3.7 with `interpolate 1` interpolates trilinearly
// between samples it puts at u = i / N of its unit cube (i = 0 .. N-1), periodically (between
// u = (N-1)/N and 1 it blends the last sample with the first), and returns 0 outside the cube.
// Checked with POV-Ray 3.7.0.10 on a 4 x 4 x 4 file holding 1 at i = 1 only and 0 elsewhere,
// seen as a pigment along x: 0 at u = 0, 1 at u = 0.25, 0 at u = 0.5, linear between (with
// `interpolate 0` the same file shows a step over [0.25, 0.5): there voxels are cells).
// So the unit cube, scaled by N * voxel per axis and moved to bounds().lo, puts POV-Ray's
// sample i on raybook's sample i, and POV-Ray's trilinear field is raybook's (to the 16-bit
// rounding, at most 1/131070; the periodic blend only mixes two zero border samples).
//
// OUT.df3 (the format: a header of three big-endian 16-bit sizes, then one big-endian value
// per sample, x fastest, then y, then z; 16-bit values read as v / 65535: the POV-Ray 3.7
// reference, the density_file pattern; the 16-bit reading checked as above with 0x8000 and
// 0xffff, which POV-Ray shows as 0.50 and 1.00). OUT.inc declares for the .pov file:
//   DensityFile   the df3 file's path, as given
//   DensityScale  the unit cube's size in the grid's space (N * voxel per axis)
//   DensityOrigin where its corner u = 0 lies (bounds().lo)
//   DensityBox    the corner of the field's bounds in the unit cube, (N-1)/N per axis
// Prints the sample counts, the largest and the mean density, and the largest rounding.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include <nanovdb/util/IO.h>

#include "core/error.h"
#include "media/vdb_density.h"

namespace {

/// Largest size a df3 header can state per axis.
constexpr long kMaxSamples = 65535;
/// How far from a whole number of voxels the bounds may lie before the grid's transform is
/// taken as something other than an axis-aligned scale and move.
constexpr double kWholeVoxel = 1e-6;

/// Append v as two big-endian bytes.
void putU16(std::vector<unsigned char>& out, long v) {
    out.push_back(static_cast<unsigned char>((v >> 8) & 0xff));
    out.push_back(static_cast<unsigned char>(v & 0xff));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: ch17_vdb_df3 IN.nvdb GRID OUT.df3 OUT.inc\n");
        return 2;
    }
    const std::string in = argv[1], gridName = argv[2], df3 = argv[3], inc = argv[4];
    try {
        const auto field = rb::loadVdbDensity(in, gridName, nullptr);
        nanovdb::Vec3d voxel(0.0);
        for (const auto& meta : nanovdb::io::readGridMetaData(in))
            if (meta.gridName == gridName) voxel = meta.voxelSize;
        const rb::AABB box = field->bounds();
        if (box.empty()) throw rb::InputError(in + ": the grid has no active voxels");
        long n[3];
        for (int a = 0; a < 3; ++a) {
            const double cells = (box.hi[a] - box.lo[a]) / voxel[a];
            n[a] = std::lround(cells) + 1;
            if (!(voxel[a] > 0.0) || std::abs(cells - std::round(cells)) > kWholeVoxel ||
                n[a] < 2 || n[a] > kMaxSamples)
                throw rb::InputError(in + ": the grid's bounds are not a whole number of voxels "
                                          "(up to 65534) per axis: only axis-aligned grids map "
                                          "to a df3 file");
        }

        std::vector<unsigned char> bytes;
        bytes.reserve(6 + 2 * n[0] * n[1] * n[2]);
        for (long size : n) putU16(bytes, size);
        double peak = 0.0, sum = 0.0, rounding = 0.0;
        long nonzero = 0;
        for (long k = 0; k < n[2]; ++k)
            for (long j = 0; j < n[1]; ++j)
                for (long i = 0; i < n[0]; ++i) {
                    const rb::Vec3 p = box.lo + rb::Vec3(i * voxel[0], j * voxel[1], k * voxel[2]);
                    const double d = field->at(p);
                    if (d > 1.0)
                        throw rb::InputError(in + ": a density above 1 (" + std::to_string(d) +
                                             "); a df3 file holds values in [0, 1]");
                    const long q = std::lround(d * 65535.0);
                    putU16(bytes, q);
                    peak = std::max(peak, d);
                    rounding = std::max(rounding, std::abs(q / 65535.0 - d));
                    sum += d;
                    nonzero += d > 0.0;
                }
        std::ofstream out(df3, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
        if (!out) throw rb::InputError(df3 + ": cannot write it");

        std::ofstream pov(inc);
        char line[512];
        pov << "// Written by ch17_vdb_df3 from " << in << ", grid '" << gridName << "'.\n";
        pov << "#declare DensityFile = \"" << df3 << "\";\n";
        std::snprintf(line, sizeof line,
                      "#declare DensityScale = <%.17g, %.17g, %.17g>;\n"
                      "#declare DensityOrigin = <%.17g, %.17g, %.17g>;\n"
                      "#declare DensityBox = <%ld / %ld, %ld / %ld, %ld / %ld>;\n",
                      n[0] * voxel[0], n[1] * voxel[1], n[2] * voxel[2], box.lo.x, box.lo.y,
                      box.lo.z, n[0] - 1, n[0], n[1] - 1, n[1], n[2] - 1, n[2]);
        pov << line;
        if (!pov) throw rb::InputError(inc + ": cannot write it");

        std::printf("%s: %ld x %ld x %ld samples, voxel %g; density max %.6f, mean %.6f over "
                    "the samples (%ld non-zero); largest 16-bit rounding %.2g\n",
                    df3.c_str(), n[0], n[1], n[2], voxel[0], peak,
                    sum / double(n[0] * n[1] * n[2]), nonzero, rounding);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ch17_vdb_df3: %s\n", e.what());
        return 1;
    }
    return 0;
}
