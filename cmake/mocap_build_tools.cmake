# The tools that make a build fast: a compiler cache, a fast linker and debug info sized for its use.
# Each is optional; what is missing is said once at configure time and the build goes on without it.
#
#   MOCAP_CCACHE          compile through ccache (default: on when ccache is found)
#   MOCAP_LLD             link with lld (default: on when the compiler can use it)
#   MOCAP_FULL_DEBUG_INFO full debug info (-g) in Debug and RelWithDebInfo; off: line tables only
#                         (-g1 with GCC, -gline-tables-only with clang), which still gives file and
#                         line in backtraces, sanitizer reports and perf, at a fraction of the size

# --- Compiler cache -------------------------------------------------------------------------------
# The cache is keyed by the compiler, its full command line and every file read, so changing a
# definition or a flag never reuses an object (tests/build/ccache_key_test.sh checks it). Two clones
# of the tree share the cache: paths under the source folder are rewritten relative to the working
# directory (CCACHE_BASEDIR) and the debug info names the source folder "." (-fdebug-prefix-map, which
# ccache also applies to the working directory it hashes); nothing else in a compile line may hold
# the checkout's path (test and benchmark paths live in the generated checkout_paths.cpp). The
# compiler cache's own folder and size are the user's (ccache's defaults: ~/.cache/ccache, 5 GB).
find_program(MOCAP_CCACHE_PROGRAM ccache)
if(MOCAP_CCACHE_PROGRAM)
  option(MOCAP_CCACHE "Compile through ccache" ON)
else()
  option(MOCAP_CCACHE "Compile through ccache" OFF)
  message(STATUS "mocap: ccache not found, every build compiles from scratch (apt-get install ccache)")
endif()
set(MOCAP_CCACHE_STATS_LOG "${PROJECT_BINARY_DIR}/ccache-stats.log"
  CACHE FILEPATH "File where ccache appends one line per compile of this build (scripts print its hit rate)")
if(MOCAP_CCACHE AND MOCAP_CCACHE_PROGRAM)
  # pch_defines,time_macros: what ccache needs to cache compiles that use a precompiled header
  # (documented in ccache's manual); the header's contents are still hashed. Depend mode takes the
  # files a compile read from the compiler's own -MD list, so a miss runs the compiler once, not the
  # preprocessor first. The inode cache remembers a file's hash by device, inode, size and times:
  # every compile of a target reads its precompiled header (110-280 MB), and hashing it again for
  # each made a cache hit cost 1.4 s where it costs 0.15 s (a warm build of build/: 232 s → 76 s).
  set(launcher ${CMAKE_COMMAND} -E env
    "CCACHE_BASEDIR=${PROJECT_SOURCE_DIR}"
    "CCACHE_SLOPPINESS=pch_defines,time_macros"
    "CCACHE_DEPEND=true"
    "CCACHE_INODECACHE=true"
    "CCACHE_STATSLOG=${MOCAP_CCACHE_STATS_LOG}"
    ${MOCAP_CCACHE_PROGRAM})
  set(CMAKE_C_COMPILER_LAUNCHER ${launcher})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher})
  add_compile_options("-fdebug-prefix-map=${PROJECT_SOURCE_DIR}=.")
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # A compile that uses a precompiled header can then also be cached in ccache's preprocessor mode.
    add_compile_options(-fpch-preprocess)
  elseif(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    # When precompiled headers are asked for (MOCAP_PCH=ON): clang's records its build time and each
    # input's mtime; without them a header rebuilt with the same content still lets the files that
    # read it hit the cache in this clone.
    add_compile_options("SHELL:-Xclang -fno-pch-timestamp" "SHELL:-Xclang -fvalidate-ast-input-files-content")
  endif()
  message(STATUS "mocap: compiling through ${MOCAP_CCACHE_PROGRAM} (base dir ${PROJECT_SOURCE_DIR})")
endif()

# --- Linker -------------------------------------------------------------------------------------
include(CheckLinkerFlag)
check_linker_flag(CXX "-fuse-ld=lld" MOCAP_HAVE_LLD)
if(MOCAP_HAVE_LLD)
  option(MOCAP_LLD "Link with lld" ON)
else()
  option(MOCAP_LLD "Link with lld" OFF)
  message(STATUS "mocap: lld not usable, linking with the default linker (apt-get install lld)")
endif()
if(MOCAP_LLD AND MOCAP_HAVE_LLD)
  add_link_options(-fuse-ld=lld)
endif()

# --- Debug info ---------------------------------------------------------------------------------
option(MOCAP_FULL_DEBUG_INFO "Full debug info (-g) in Debug and RelWithDebInfo builds; off: line tables only" OFF)
if(NOT MOCAP_FULL_DEBUG_INFO)
  # Given after the build type's -g, so it wins.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    add_compile_options($<$<CONFIG:Debug,RelWithDebInfo>:-gline-tables-only>)
  else()
    add_compile_options($<$<CONFIG:Debug,RelWithDebInfo>:-g1>)
  endif()
endif()

# --- Precompiled headers --------------------------------------------------------------------------
# Off by default for clang compiling through ccache: clang's precompiled header records the absolute
# paths of its inputs and ccache hashes its bytes, so in another clone every file that reads it
# misses the cache (a second clone's sanitizer build took 15 of 216 objects from the cache). Without
# it a test file compiles about 25 % slower once (take_test.cpp 4.6 s instead of 3.6 s of CPU) and
# every later clone compiles nothing.
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang" AND MOCAP_CCACHE AND MOCAP_CCACHE_PROGRAM)
  set(mocap_pch_default OFF)
  message(STATUS "mocap: no precompiled headers with clang and ccache (clang's would keep clones from sharing the cache; -DMOCAP_PCH=ON to use them)")
else()
  set(mocap_pch_default ON)
endif()
option(MOCAP_PCH "Precompile the heavy headers that many files of a target read" ${mocap_pch_default})
# mocap_precompile_headers(<target> <header>...): <header>s given as <...> so the generated
# cmake_pch.hxx holds no path of this checkout (a compiler cache then reuses it across clones).
function(mocap_precompile_headers target)
  if(MOCAP_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()
# The standard headers most of our files read, for the precompiled headers of each target.
set(MOCAP_PCH_STD_HEADERS
  <algorithm> <array> <cmath> <cstdint> <cstdio> <cstring> <filesystem> <functional> <limits> <map>
  <memory> <optional> <set> <sstream> <string> <string_view> <utility> <vector>)
# mocap_reuse_precompiled_headers(<target> <from>): <target> uses <from>'s precompiled header (both
# must be compiled with the same flags).
function(mocap_reuse_precompiled_headers target from)
  if(MOCAP_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
