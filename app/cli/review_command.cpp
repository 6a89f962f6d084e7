// `mocap review`: checks the command line here, then runs the `mocap-review` program installed
// beside `mocap` with the same arguments. The review renders the studio's own 3D view, so it needs
// Qt, VTK and OpenGL; keeping them in a program of their own keeps every other command's start-up
// free of them.
#include "commands.h"
#include "cli_error.h"
#include "review_arguments.h"
#include "virtual_display.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

namespace mocap::cli {

namespace {

/// The argument list that hands `a` to mocap-review, as `mocap review` was given them.
std::vector<std::string> reviewArgv(const ReviewArguments& a)
{
  std::vector<std::string> argv = {a.take, "-o", a.output, "--size", a.size, "--trails", std::to_string(a.trails)};
  const auto optional = [&argv](const char* name, const std::optional<std::string>& value) {
    if (value)
      argv.insert(argv.end(), {name, *value});
  };
  optional("--frames", a.frames);
  optional("--video", a.video);
  optional("--mesh", a.mesh);
  optional("--binding", a.binding);
  optional("--solve", a.solve);
  optional("--rig-shapes", a.rigShapes);
  optional("--select", a.select);
  if (a.video) {
    char offset[64];
    std::snprintf(offset, sizeof offset, "%.17g", a.offset);
    argv.insert(argv.end(), {"--offset", offset});
  }
  if (a.json)
    argv.emplace_back("--json");
  return argv;
}

std::filesystem::path reviewProgram()
{
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return (error ? std::filesystem::path() : self.parent_path()) / "mocap-review";
}

/// Whether there is an X display: the review renders in VTK's off-screen X11 window (a Wayland
/// session without Xwayland does not do).
bool hasXDisplay()
{
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

/// Whether `program` is an executable on the PATH.
bool onPath(const std::string& program)
{
  const char* path = std::getenv("PATH");
  std::string folders = path ? path : "";
  for (std::size_t start = 0; start <= folders.size();) {
    const std::size_t end = std::min(folders.find(':', start), folders.size());
    const std::filesystem::path candidate = std::filesystem::path(folders.substr(start, end - start)) / program;
    if (::access(candidate.c_str(), X_OK) == 0)
      return true;
    start = end + 1;
  }
  return false;
}

[[noreturn]] void execute(std::vector<std::string> argv)
{
  std::vector<char*> pointers;
  for (std::string& argument : argv)
    pointers.push_back(argument.data());
  pointers.push_back(nullptr);
  std::cout.flush();
  ::execvp(pointers[0], pointers.data());
  std::cerr << "mocap review: cannot run " << argv[0] << '\n';
  std::exit(kExitBadInput);
}

int runReview(const ReviewArguments& arguments)
{
  (void)parseReviewSize(arguments.size);
  const std::filesystem::path program = reviewProgram();
  if (::access(program.c_str(), X_OK) != 0) {
    std::cerr << "mocap review: " << program.string() << " is missing (it is built with the studio)\n";
    return kExitBadInput;
  }
  std::vector<std::string> argv = reviewArgv(arguments);
  argv.insert(argv.begin(), program.string());
  if (hasXDisplay())
    execute(std::move(argv));
  // Debian's VTK renders through X11 only (no EGL or OSMesa): without a display, a virtual one.
  if (!onPath("Xvfb")) {
    std::cerr << "mocap review: rendering needs a display; there is none and Xvfb (Debian package xvfb) is "
                 "not installed\n";
    return kExitBadInput;
  }
  return runOnVirtualDisplay(argv, "1920x1080x24");
}

} // namespace

Command addReview(CLI::App& mocap)
{
  auto arguments = std::make_shared<ReviewArguments>();
  CLI::App* command = mocap.add_subcommand(
      "review", "review video: the 3D view (markers, trails, mesh or solved rig) beside the reference video, "
                "frame number and timecode burnt in");
  defineReviewOptions(*command, *arguments);
  return {command, [arguments] { return runReview(*arguments); }};
}

} // namespace mocap::cli
