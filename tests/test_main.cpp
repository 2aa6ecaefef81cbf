// The Catch2 main for raybook's test binary.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
