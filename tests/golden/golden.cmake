# Golden-image machinery: rb_blockstats and rb_add_golden_test(). The comparison itself is
# ./rt --compare (src/app/compare.cpp, image_compare.cpp, block_stats.cpp), so the golden
# tests, make check, make grade and a student's own comparison run the same code.
#
# Included from the top-level CMakeLists.txt.
#
# Provides:
#   rb_blockstats                 writes a Monte Carlo golden's reference block statistics
#   RB_GOLDEN_TEST_SOURCES        the Catch2 tests of the metric (golden_compare.cpp, no main)
#   rb_add_golden_test(TEST_NAME RT_TARGET SCENE_PATH [rt args...])
#       a ctest test (label "golden") that renders SCENE_PATH (relative to the repository root)
#       with RT_TARGET and compares it with golden/NAME.png (RT_TARGET --compare); reports go
#       to build/golden-report/ under the test's name, so several tests of one scene can run in
#       parallel

set(RB_GOLDEN_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/golden_compare.cpp
                           ${CMAKE_CURRENT_LIST_DIR}/block_stats_test.cpp)
set(RB_GOLDEN_RUNNER ${CMAKE_CURRENT_LIST_DIR}/run_golden.sh)

add_executable(rb_blockstats ${CMAKE_CURRENT_LIST_DIR}/blockstats_main.cpp)
target_link_libraries(rb_blockstats PRIVATE raybook)

# Register one golden-image test. Extra arguments after SCENE_PATH are passed on to rt.
function(rb_add_golden_test TEST_NAME RT_TARGET SCENE_PATH)
    add_test(NAME ${TEST_NAME}
             COMMAND bash ${RB_GOLDEN_RUNNER} $<TARGET_FILE:${RT_TARGET}> ${SCENE_PATH}
                     ${CMAKE_SOURCE_DIR}/golden ${CMAKE_BINARY_DIR}/golden-report
                     --report-name=${TEST_NAME} ${ARGN})
    set_tests_properties(${TEST_NAME} PROPERTIES LABELS golden)
endfunction()
