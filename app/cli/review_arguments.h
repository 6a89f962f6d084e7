#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace mocap::cli {

/// The options of `mocap review`, defined once: `mocap` parses them to check the command line and
/// show the usage, then hands the arguments to the `mocap-review` program (which links the studio's
/// Qt/VTK view, so `mocap` itself stays a small program), which parses them again to render.
struct ReviewArguments
{
  std::string take;
  std::string output;
  std::optional<std::string> frames;
  std::string size = "1280x720";
  std::optional<std::string> video;
  double offset = 0.0;
  std::optional<std::string> mesh;
  std::optional<std::string> binding;
  std::optional<std::string> solve;
  std::optional<std::string> rigShapes;
  std::optional<std::string> select;
  int trails = 50;
  bool json = false;
};

/// Adds `review`'s positionals and options to `command`, bound to `arguments`.
void defineReviewOptions(CLI::App& command, ReviewArguments& arguments);

/// The width and height of `--size WxH`; UsageError for another form, odd sides or a side outside
/// [64, 7680]. O(1).
[[nodiscard]] std::pair<int, int> parseReviewSize(const std::string& text);

} // namespace mocap::cli
