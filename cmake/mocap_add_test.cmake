# mocap_add_test(<name> LABEL <label> SOURCES <files...> LIBRARIES <targets...> [NO_PCH])
# A GoogleTest executable whose cases are discovered one CTest test each. It links the shared test
# support (test_support.h, shell_run.h, the checkout's paths: never relative to the cwd) and reuses
# its precompiled header; NO_PCH for a test linking Qt, which compiles with -fPIC and so cannot.
include(GoogleTest)
function(mocap_add_test name)
  cmake_parse_arguments(ARG "NO_PCH" "LABEL" "SOURCES;LIBRARIES" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} mocap_test_support GTest::gtest GTest::gtest_main)
  mocap_enable_warnings(${name})
  if(NOT ARG_NO_PCH)
    mocap_reuse_precompiled_headers(${name} mocap_test_support)
  endif()
  gtest_discover_tests(${name} PROPERTIES LABELS ${ARG_LABEL} DISCOVERY_TIMEOUT 60)
endfunction()
