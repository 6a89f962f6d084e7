// mocap.write_review_video: the review video `mocap review` renders (the studio's 3D view beside the
// reference video, frame and timecode burnt in). That rendering is the studio's Qt/VTK view, which
// this module must not link (it binds the Qt-free core only, so importing it loads no Qt), so the
// call runs the `mocap review` command line and hands on its progress, errors and JSON summary.

#include "bindings.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/process_list.h"
#include "mocap/base/job_control.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/io/take_io.h"
#include "mocap/model/take.h"

#include <pybind11/stl.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <signal.h>
#include <sys/types.h>

namespace py = pybind11;
using namespace pybind11::literals;

namespace mocap::python {

namespace {

std::string fspath(const py::handle& path)
{
  return py::str(py::module_::import("os").attr("fspath")(path));
}

bool isExecutable(const std::string& path)
{
  const py::module_ os = py::module_::import("os");
  return os.attr("path").attr("isfile")(path).cast<bool>() && os.attr("access")(path, os.attr("X_OK")).cast<bool>();
}

/// The `mocap` command line: `cli` when given, else $MOCAP_CLI, else the build tree's bin/ beside
/// this module's folder (build/python → build/bin), else `mocap` on the PATH.
std::string mocapCli(const py::object& cli)
{
  const py::module_ os = py::module_::import("os");
  std::vector<std::string> tried;
  if (!cli.is_none()) {
    tried.push_back(fspath(cli));
  } else if (const py::object fromEnvironment = os.attr("environ").attr("get")("MOCAP_CLI");
             !fromEnvironment.is_none() && !fromEnvironment.cast<std::string>().empty()) {
    tried.push_back(fromEnvironment.cast<std::string>());
  } else {
    const py::object folder = os.attr("path").attr("dirname")(
        os.attr("path").attr("abspath")(py::module_::import("mocap").attr("__file__")));
    tried.push_back(py::str(os.attr("path").attr("join")(folder, "..", "bin", "mocap")));
    const py::object onPath = py::module_::import("shutil").attr("which")("mocap");
    tried.push_back(onPath.is_none() ? std::string("mocap on the PATH") : onPath.cast<std::string>());
  }
  for (const std::string& path : tried)
    if (isExecutable(path))
      return path;
  std::string names;
  for (const std::string& path : tried)
    names += (names.empty() ? "" : ", ") + path;
  throw IoError("write_review_video runs the `mocap` command line (its review needs mocap-review, built with the "
                "studio) and found none (tried " + names + "); pass cli= or set MOCAP_CLI");
}

/// A folder for the files a call hands to `mocap review` (a Take or Binding given as an object),
/// removed when the call ends.
class TemporaryFolder
{
public:
  TemporaryFolder() : m_path(py::module_::import("tempfile").attr("mkdtemp")("prefix"_a = "mocap-review-").cast<std::string>()) {}
  ~TemporaryFolder()
  {
    try {
      py::module_::import("shutil").attr("rmtree")(m_path, "ignore_errors"_a = true);
    } catch (py::error_already_set&) {
      // Nothing to do: a folder left in the system's temporary folder is harmless.
    }
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;

  [[nodiscard]] std::string file(const std::string& name) const { return m_path + "/" + name; }

private:
  std::string m_path;
};

/// The take as a path `mocap review` reads: a path as given, a mocap.Take written as a C3D.
std::string takePath(const py::object& take, const TemporaryFolder& folder)
{
  if (!py::isinstance<Take>(take))
    return fspath(take);
  const std::string path = folder.file("take.c3d");
  writeTake(take.cast<const Take&>(), path);
  return path;
}

std::string bindingPath(const py::object& binding, const TemporaryFolder& folder)
{
  if (!py::isinstance<MeshBinding>(binding))
    return fspath(binding);
  const std::string path = folder.file("binding.json");
  writeFileAtomically(path, bindingJson(binding.cast<const MeshBinding&>()));
  return path;
}

/// `size` as --size takes it: "WxH" or (width, height).
std::string sizeText(const py::object& size)
{
  if (py::isinstance<py::str>(size))
    return size.cast<std::string>();
  const auto [width, height] = size.cast<std::pair<long long, long long>>();
  return std::to_string(width) + "x" + std::to_string(height);
}

std::string joined(const std::vector<std::string>& parts, const char* separator = ",")
{
  std::string text;
  for (const std::string& part : parts)
    text += (text.empty() ? "" : separator) + part;
  return text;
}

/// What `mocap review` said on stderr besides its progress: its own lines ("mocap review: …",
/// given without that prefix), whether it printed its usage line (a usage error), and every line
/// (with Qt's and xvfb-run's remarks).
struct ReviewMessages
{
  std::vector<std::string> ours;
  std::vector<std::string> lines;
  bool usage = false;
};

ReviewMessages reviewMessages(const std::string& text)
{
  static const std::string prefix = "mocap review: ";
  ReviewMessages said;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) {
    if (line.empty())
      continue;
    said.lines.push_back(line);
    if (line.rfind(prefix, 0) == 0)
      said.ours.push_back(line.substr(prefix.size()));
    said.usage = said.usage || line.rfind("usage: mocap review", 0) == 0;
  }
  return said;
}

/// The processes called `name` in process group `group`. O(#processes).
std::vector<pid_t> processesNamed(pid_t group, const std::string& name)
{
  std::vector<pid_t> found;
  for (const ProcessEntry& process : runningProcesses())
    if (process.group == group && process.name == name)
      found.push_back(process.pid);
  return found;
}

/// Stops the review as Ctrl+C would: SIGINT to mocap-review, which stops at its next frame and
/// removes its partial video, and only to it: without a display it runs under xvfb-run in the
/// same process group, and an X server stopped with it (Xvfb ends on SIGINT too) would end it
/// mid-frame, leaving its partial video. Before mocap-review runs, the whole group is ended (SIGTERM): nothing
/// is written yet. Waits for the review to end.
void interrupt(const py::object& process)
{
  const auto group = process.attr("pid").cast<pid_t>();  // start_new_session: the child leads its group
  const std::vector<pid_t> reviews = processesNamed(group, "mocap-review");
  if (reviews.empty())
    ::killpg(group, SIGTERM);
  for (const pid_t review : reviews)
    ::kill(review, SIGINT);
  try {
    process.attr("wait")("timeout"_a = 30);
  } catch (py::error_already_set&) {
    ::killpg(group, SIGKILL);  // it did not stop: end it rather than leave it running
    process.attr("wait")();
  }
}

struct ReviewRun
{
  int exitCode = 0;
  std::string out;
  std::string messages;  ///< the lines on stderr that are not progress
};

/// Runs `arguments`, handing each "mocap review: N of M frames" line to `progress`; a callback
/// that returns False (mocap.Cancelled) or Ctrl+C (KeyboardInterrupt) interrupts the review.
ReviewRun runReview(const py::list& arguments, const py::object& progress)
{
  const py::module_ subprocess = py::module_::import("subprocess");
  const py::object process =
      subprocess.attr("Popen")(arguments, "stdout"_a = subprocess.attr("PIPE"), "stderr"_a = subprocess.attr("PIPE"),
                               "text"_a = true, "start_new_session"_a = true);
  ReviewRun run;
  try {
    for (const py::handle line : process.attr("stderr")) {
      const std::string text = line.cast<std::string>();
      long long done = 0, total = 0;
      if (std::sscanf(text.c_str(), "mocap review: %lld of %lld frames", &done, &total) != 2 || total <= 0) {
        run.messages += text;
        continue;
      }
      if (!progress.is_none()) {
        const py::object answer = progress(static_cast<double>(done) / static_cast<double>(total));
        if (!answer.is_none() && !answer.cast<bool>()) {
          interrupt(process);
          throw JobCancelled();
        }
      }
    }
    run.out = process.attr("stdout").attr("read")().cast<std::string>();
    run.exitCode = process.attr("wait")().cast<int>();
  } catch (py::error_already_set&) {
    interrupt(process);  // KeyboardInterrupt or the callback's exception: no review goes on behind it
    throw;
  }
  return run;
}

py::dict writeReviewVideo(const py::object& output, const py::object& take, const std::optional<std::pair<long long, long long>>& frames,
                          const py::object& size, const py::object& video, double offset, const py::object& mesh,
                          const py::object& binding, const py::object& solve, const py::object& rigShapes,
                          const std::optional<std::vector<std::string>>& select, int trails, const py::object& progress,
                          const py::object& cli)
{
  const std::string program = mocapCli(cli);
  const TemporaryFolder folder;
  py::list arguments;
  for (const std::string& argument : {program, std::string("review"), takePath(take, folder), std::string("-o"),
                                      fspath(output), std::string("--size"), sizeText(size), std::string("--trails"),
                                      std::to_string(trails), std::string("--json")})
    arguments.append(argument);
  const auto option = [&arguments](const char* name, const std::string& value) {
    arguments.append(name);
    arguments.append(value);
  };
  if (frames)
    option("--frames", std::to_string(frames->first) + ":" + std::to_string(frames->second));
  if (!video.is_none()) {
    option("--video", fspath(video));
    option("--offset", py::str(py::float_(offset)).cast<std::string>());
  }
  if (!mesh.is_none())
    option("--mesh", fspath(mesh));
  if (!binding.is_none())
    option("--binding", bindingPath(binding, folder));
  if (!solve.is_none())
    option("--solve", fspath(solve));
  if (!rigShapes.is_none())
    option("--rig-shapes", fspath(rigShapes));
  if (select)
    option("--select", joined(*select));
  const ReviewRun run = runReview(arguments, progress);
  const ReviewMessages said = reviewMessages(run.messages);
  // A summary on stdout means the video was written, whatever the exit code: xvfb-run now and then
  // fails to remove its own temporary folder after the review and then exits 5.
  if (run.out.find('{') != std::string::npos) {
    py::dict summary = py::module_::import("json").attr("loads")(run.out);
    summary["warnings"] = said.lines;  // e.g. no MP4 encoder here: Motion JPEG AVI written instead
    return summary;
  }
  // mocap's exit codes: 2 bad usage (an option out of range, with the usage line), 1 bad input.
  const std::string what = said.ours.empty() ? joined(said.lines, "\n") : joined(said.ours, "\n");
  if (run.exitCode == 2 || said.usage)
    throw InvalidArgument(what);
  throw IoError(what.empty() ? "mocap review ended with exit code " + std::to_string(run.exitCode) : what);
}

} // namespace

void bindReviewVideo(py::module_& m)
{
  m.def("write_review_video", &writeReviewVideo, py::arg("output"), py::arg("take"), py::kw_only(),
        py::arg("frames") = py::none(), py::arg("size") = "1280x720", py::arg("video") = py::none(),
        py::arg("offset") = 0.0, py::arg("mesh") = py::none(), py::arg("binding") = py::none(),
        py::arg("solve") = py::none(), py::arg("rig_shapes") = py::none(), py::arg("select") = py::none(),
        py::arg("trails") = 50, py::arg("progress") = py::none(), py::arg("cli") = py::none(),
        "Writes a review video (.mp4: H.264, else MPEG-4, else Motion JPEG .avi beside it; .avi: Motion JPEG) "
        "of `take` (a path, or a mocap.Take, handed on as a temporary C3D) as `mocap review` renders it: the "
        "studio's 3D view (markers, trails; the face `mesh` driven through `binding`, or the rig `solve` "
        "solved to the take) beside the reference `video` (`offset` s before the take's first frame), "
        "frame and timecode burnt in. frames=(first, last) as the take numbers them; size 'WxH' or (w, h); "
        "select: labels drawn selected; binding: a path or a mocap.Binding. The rendering is the studio's "
        "Qt/VTK view, which this module does not load: the call runs the `mocap` command line (cli=, else "
        "$MOCAP_CLI, else the build's bin/mocap beside this module's folder, else `mocap` on the PATH) and "
        "its mocap-review, under xvfb-run when there is no display, and raises IoError when they are "
        "missing. Returns `mocap review --json`'s summary (output, codec, container, frames, width, height, "
        "frame_rate, seconds, ...) plus 'warnings' (what it printed on stderr). progress(fraction) after every tenth of the frames; "
        "returning False (mocap.Cancelled) or Ctrl+C (KeyboardInterrupt) stops the review, which leaves no "
        "partial file. Errors: InvalidArgument for an option mocap review refuses, IoError for a file it "
        "cannot read or write, with its message.");
}

} // namespace mocap::python
