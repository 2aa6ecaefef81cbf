/// \file
/// rb_blockstats: writes the reference block statistics of a Monte Carlo golden image from
/// several renders of its scene with different seeds (run_golden.sh --update-stats runs it).
///
/// Usage: rb_blockstats OUT.stats RENDER.png RENDER.png RENDER.png RENDER.png [...]
/// Exit status: 0 written, 2 usage or I/O error.
#include <iostream>
#include <vector>

#include "app/block_stats.h"

int main(int argc, char** argv) {
    if (argc < 6) {
        std::cerr << "usage: rb_blockstats OUT.stats RENDER.png ... (at least 4 renders)\n";
        return 2;
    }
    try {
        std::vector<rb::golden::Image> renders;
        for (int i = 2; i < argc; ++i) renders.push_back(rb::golden::load_png(argv[i]));
        rb::golden::save_block_stats(argv[1], rb::golden::block_stats(renders));
    } catch (const std::exception& e) {
        std::cerr << "rb_blockstats: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
