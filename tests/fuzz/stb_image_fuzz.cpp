/// \file
/// Built into fuzz_compare under RB_FUZZ only: Debian's stb_image (the header libstb is built
/// from) compiled here with libFuzzer's and the sanitizers' instrumentation, so the fuzzer sees
/// the decoder's branches and ASan its reads; the library itself is not instrumented. These
/// definitions take the place of libstb's in the target.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
