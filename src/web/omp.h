/// \file
/// OpenMP's runtime calls for the WebAssembly build, which runs on one thread: the compiler
/// ignores the pragmas without -fopenmp, and these answer as OpenMP does with one thread.
/// The native build never sees this header (src/web is on the include path only there).
#pragma once

inline int omp_get_num_threads() {
    return 1;
}
inline int omp_get_max_threads() {
    return 1;
}
inline int omp_get_thread_num() {
    return 0;
}
inline void omp_set_num_threads(int) {}
