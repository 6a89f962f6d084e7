#include "virtual_display.h"

#include "stop_signal.h"

#include "mocap/base/error.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace mocap::cli {

namespace {

constexpr int kStartMilliseconds = 20000;

/// argv as the exec functions take it (pointers into `strings`, null-terminated).
std::vector<char*> execArgv(std::vector<std::string>& strings)
{
  std::vector<char*> pointers;
  for (std::string& s : strings)
    pointers.push_back(s.data());
  pointers.push_back(nullptr);
  return pointers;
}

/// A child that replaces itself with `argv` (searched on the PATH); returns its process id.
/// `prepare` runs in the child first. Exits 127 in the child when the program cannot run.
template <typename Prepare>
pid_t spawn(std::vector<std::string> argv, Prepare prepare)
{
  std::vector<char*> pointers = execArgv(argv);  // built before fork: no allocation in the child
  const pid_t child = ::fork();
  if (child < 0)
    throw IoError("mocap review: cannot start a process");
  if (child == 0) {
    prepare();
    ::execvp(pointers[0], pointers.data());
    ::_exit(127);
  }
  return child;
}

/// The display number Xvfb writes on `fd` once it accepts connections, or -1 (it ended, or took
/// longer than kStartMilliseconds).
int readDisplayNumber(int fd)
{
  std::string text;
  for (;;) {
    pollfd ready{fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, kStartMilliseconds);
    if (polled < 0 && errno == EINTR)
      continue;
    char c = 0;
    if (polled <= 0 || ::read(fd, &c, 1) != 1)
      return -1;
    if (c == '\n')
      return text.empty() ? -1 : std::atoi(text.c_str());
    text += c;
  }
}

/// Starts Xvfb on a free display in a session of its own; returns its process id and sets `display`.
pid_t startXvfb(const std::string& screen, int& display)
{
  int pipeFds[2];
  if (::pipe(pipeFds) != 0)
    throw IoError("mocap review: cannot start Xvfb (no pipe)");
  const int writeEnd = pipeFds[1];
  // -noreset: the review opens and closes a connection to probe OpenGL before its window; with no
  // client left the server would reset, and the window's connection, made meanwhile, would fail.
  const pid_t xvfb = spawn({"Xvfb", "-displayfd", std::to_string(writeEnd), "-screen", "0", screen, "-nolisten", "tcp",
                            "-noreset"},
                           [&] {
                             ::setsid();
                             ::prctl(PR_SET_PDEATHSIG, SIGTERM);
                             ::close(pipeFds[0]);
                             const int null = ::open("/dev/null", O_WRONLY);
                             if (null >= 0) {
                               ::dup2(null, STDOUT_FILENO);
                               ::dup2(null, STDERR_FILENO);
                             }
                           });
  ::close(writeEnd);
  display = readDisplayNumber(pipeFds[0]);
  ::close(pipeFds[0]);
  if (display < 0) {
    ::kill(xvfb, SIGTERM);
    ::waitpid(xvfb, nullptr, 0);
    throw IoError("mocap review: the virtual X server (Xvfb) did not start");
  }
  return xvfb;
}

/// Waits for `child`, passing SIGINT on to it when `stop` is raised; its exit code (128 + signal).
int waitPassingOnStop(pid_t child, const std::atomic<bool>& stop)
{
  bool passedOn = false;
  for (;;) {
    int status = 0;
    if (::waitpid(child, &status, 0) == child)
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    if (errno != EINTR)
      return 1;
    if (stop.load() && !passedOn) {
      ::kill(child, SIGINT);  // it stops at its next frame; a second signal changes nothing
      passedOn = true;
    }
  }
}

} // namespace

int runOnVirtualDisplay(const std::vector<std::string>& argv, const std::string& screen)
{
  const std::atomic<bool>& stop = installStopSignals();
  int display = -1;
  const pid_t xvfb = startXvfb(screen, display);
  if (stop.load()) {  // stopped while the server started: nothing to render
    ::kill(xvfb, SIGTERM);
    ::waitpid(xvfb, nullptr, 0);
    return 130;
  }
  ::setenv("DISPLAY", (":" + std::to_string(display)).c_str(), 1);
  const pid_t program = spawn(argv, [] {
    struct sigaction standard {};
    standard.sa_handler = SIG_DFL;
    ::sigaction(SIGINT, &standard, nullptr);
    ::sigaction(SIGTERM, &standard, nullptr);
  });
  const int code = waitPassingOnStop(program, stop);
  ::kill(xvfb, SIGTERM);
  ::waitpid(xvfb, nullptr, 0);
  return code;
}

} // namespace mocap::cli
