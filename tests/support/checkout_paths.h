#pragma once

// Paths of this checkout and its build, for tests and benchmarks. They are generated into one small
// source file (checkout_paths.cpp.in) rather than passed as compile definitions, so no other compile
// line names the checkout: a compiler cache shared by two clones of the tree reuses their objects.

namespace mocap::checkout {

[[nodiscard]] const char* sourceDir();     ///< the repository root (README.md)
[[nodiscard]] const char* testDataDir();   ///< tests/data
[[nodiscard]] const char* sampleDir();     ///< resources/sample: the bundled take, mesh, binding and rig
[[nodiscard]] const char* baselineDir();   ///< tests/baselines: committed render baselines
[[nodiscard]] const char* sharedDataDir(); ///< ../shared/data beside the checkout (may be missing)
[[nodiscard]] const char* binDir();        ///< where the executables are built (mocap, mocap-review)
[[nodiscard]] const char* cliProgram();    ///< the `mocap` command line
[[nodiscard]] const char* testBuildDir();  ///< build/tests: where GUI tests leave renders to look at
[[nodiscard]] const char* chromium();      ///< Chromium found at configure time, or ""

} // namespace mocap::checkout
