# mocap_add_test(<name> LABEL <label> SOURCES <files...> LIBRARIES <targets...>)
# A GoogleTest executable whose cases are discovered one CTest test each, with the test data
# folder and the bundled sample passed as compile definitions (never relative to the cwd).
include(GoogleTest)
function(mocap_add_test name)
  cmake_parse_arguments(ARG "" "LABEL" "SOURCES;LIBRARIES" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    MOCAP_TEST_DATA="${PROJECT_SOURCE_DIR}/tests/data"
    MOCAP_SAMPLE_DIR="${PROJECT_SOURCE_DIR}/resources/sample"
    MOCAP_CLI="$<TARGET_FILE:mocap>")
  mocap_enable_warnings(${name})
  gtest_discover_tests(${name} PROPERTIES LABELS ${ARG_LABEL} DISCOVERY_TIMEOUT 60)
endfunction()
