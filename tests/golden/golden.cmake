# Golden-image machinery: the rb_imgdiff comparison tool and rb_add_golden_test().
#
# Included from the top-level CMakeLists.txt after PkgConfig::STB exists (pkg_check_modules(STB
# REQUIRED IMPORTED_TARGET stb)) and CMAKE_CXX_STANDARD is set.
#
# Provides:
#   rb_golden_compare             static library: image_compare.cpp (PNG I/O, thresholds, metric);
#                                 carries its include directory and PkgConfig::STB
#   rb_imgdiff                    the comparison CLI used by run_golden.sh
#   rb_blockstats                 writes a Monte Carlo golden's reference block statistics
#   RB_GOLDEN_COMPARE_SOURCES     image_compare.cpp and block_stats.cpp, for unit tests
#   RB_GOLDEN_INCLUDE_DIR         directory holding image_compare.h
#   RB_GOLDEN_TEST_SOURCES        the Catch2 tests of the metric (golden_compare.cpp, no main)
#   rb_add_golden_test(TEST_NAME RT_TARGET SCENE_PATH [rt args...])
#       a ctest test (label "golden") that renders SCENE_PATH (relative to the repository root)
#       with RT_TARGET and compares it with golden/NAME.png; reports go to build/golden-report/
#       under the test's name, so several tests of one scene can run in parallel

set(RB_GOLDEN_INCLUDE_DIR ${CMAKE_CURRENT_LIST_DIR})
set(RB_GOLDEN_COMPARE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/image_compare.cpp
                              ${CMAKE_CURRENT_LIST_DIR}/block_stats.cpp)
set(RB_GOLDEN_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/golden_compare.cpp
                           ${CMAKE_CURRENT_LIST_DIR}/block_stats_test.cpp)
set(RB_GOLDEN_RUNNER ${CMAKE_CURRENT_LIST_DIR}/run_golden.sh)

add_library(rb_golden_compare STATIC ${RB_GOLDEN_COMPARE_SOURCES})
target_include_directories(rb_golden_compare PUBLIC ${RB_GOLDEN_INCLUDE_DIR})
target_link_libraries(rb_golden_compare PUBLIC PkgConfig::STB)

add_executable(rb_blockstats ${CMAKE_CURRENT_LIST_DIR}/blockstats_main.cpp)
target_link_libraries(rb_blockstats PRIVATE rb_golden_compare)

add_executable(rb_imgdiff ${CMAKE_CURRENT_LIST_DIR}/imgdiff.cpp)
target_link_libraries(rb_imgdiff PRIVATE rb_golden_compare)
target_include_directories(rb_imgdiff PRIVATE ${CMAKE_SOURCE_DIR}/src)

# Register one golden-image test. Extra arguments after SCENE_PATH are passed on to rt.
function(rb_add_golden_test TEST_NAME RT_TARGET SCENE_PATH)
    add_test(NAME ${TEST_NAME}
             COMMAND bash ${RB_GOLDEN_RUNNER} $<TARGET_FILE:${RT_TARGET}> ${SCENE_PATH}
                     ${CMAKE_SOURCE_DIR}/golden ${CMAKE_BINARY_DIR}/golden-report
                     $<TARGET_FILE:rb_imgdiff> --report-name=${TEST_NAME} ${ARGN})
    set_tests_properties(${TEST_NAME} PROPERTIES LABELS golden)
endfunction()
