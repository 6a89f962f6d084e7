# mocap_add_test(<name> LABEL <label> SOURCES <files...> LIBRARIES <targets...> [NO_PCH])
# A GoogleTest executable whose cases are discovered one CTest test each. It links the shared test
# support (test_support.h, shell_run.h, the checkout's paths: never relative to the cwd) and reuses
# its precompiled header; NO_PCH for a test linking Qt, which compiles with -fPIC and so cannot.
include(GoogleTest)
include(mocap_unity_build)

# mocap_optimize_as_test_code(<target>...): test code compiles at -O1 in optimized builds (it comes
# after CMake's -O2 on the command line). It only drives the library, which stays at -O2 as users run
# it; a test file's macro-heavy bodies took 40 % longer to compile at -O2 (provenance_test.cpp: 8.6 s
# of CPU against 6.2 s at -O1, without the precompiled header). Targets that share a precompiled
# header must all use it, as their compile flags must match. GCC's maybe-uninitialized analysis at
# -O1 reports Eigen's own storage copies in test bodies (a known false positive of that level); the
# library, at -O2, keeps the warning.
function(mocap_optimize_as_test_code)
  foreach(target ${ARGN})
    target_compile_options(${target} PRIVATE $<$<NOT:$<CONFIG:Debug>>:-O1>
      $<$<AND:$<NOT:$<CONFIG:Debug>>,$<CXX_COMPILER_ID:GNU>>:-Wno-maybe-uninitialized>)
  endforeach()
endfunction()

function(mocap_add_test name)
  cmake_parse_arguments(ARG "NO_PCH" "LABEL" "SOURCES;LIBRARIES" ${ARGN})
  mocap_unity_sources(sources ${name} ${ARG_SOURCES})
  add_executable(${name} ${sources})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} mocap_test_support GTest::gtest GTest::gtest_main)
  mocap_enable_warnings(${name})
  mocap_optimize_as_test_code(${name})
  if(NOT ARG_NO_PCH)
    mocap_reuse_precompiled_headers(${name} mocap_test_support)
  endif()
  gtest_discover_tests(${name} PROPERTIES LABELS ${ARG_LABEL} DISCOVERY_TIMEOUT 60)
endfunction()
