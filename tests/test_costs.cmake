# Read by ctest (a TEST_INCLUDE_FILES script of tests/CMakeLists.txt), after the unit tests
# Catch2 discovered: the slowest of them gets a COST, so that ctest -j starts it first on a
# fresh clone (see tests/CMakeLists.txt, "The order on a fresh clone").
# Source: seconds in a fresh clone's CI, 2026-11-27 (sanitizer tree: 240 s of a 797 s ctest;
# normal tree: 15 s of a 38 s unit and golden run, in which it started last).
foreach(test IN LISTS raybook_tests_TESTS)
  if(test MATCHES "^Scenario: random legal scenes of every chapter")
    set_tests_properties("${test}" PROPERTIES COST 240)
  endif()
endforeach()
