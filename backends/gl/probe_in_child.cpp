#include "backends/gl/probe_in_child.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace backends::gl {
namespace {

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n') c = ' ';
  return s;
}

std::string describeStatus(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

void reap(pid_t child, int& status) {
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

int probeTimeoutSeconds() {
  if (const char* text = std::getenv("LIGHTCTS_PROBE_TIMEOUT_S")) {
    char* end = nullptr;
    const long seconds = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && seconds > 0 && seconds < 100000) return int(seconds);
  }
  return 30;
}

std::string probeAnswer(const std::function<DeviceInfo()>& probe) {
  try {
    const DeviceInfo d = probe();
    return "ok\n" + oneLine(d.name) + "\n" + oneLine(d.driver) + "\n" + oneLine(d.driverVersion) + "\n" +
           oneLine(d.apiVersion) + "\n";
  } catch (const std::exception& e) {
    return "error\n" + oneLine(e.what()) + "\n";
  }
}

ProbeResult probeInChild(const std::string& backend, const std::string& driver) {
  const int timeoutSeconds = probeTimeoutSeconds();
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return {std::nullopt, "cannot create a pipe for the probe"};
  // Built before fork: the child calls only async-signal-safe functions.
  const std::vector<std::string> argv = {"/proc/self/exe", "probe-driver", "--backend", backend, "--driver", driver};
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return {std::nullopt, "cannot start the probe"};
  }
  if (child == 0) {
    ::setpgid(0, 0);  // its own group, so a timeout kills whatever it started
    ::dup2(fds[1], STDOUT_FILENO);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  ::setpgid(child, child);  // also here: no race with the kill below
  ::close(fds[1]);

  std::string text;
  bool timedOut = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) {
      timedOut = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, int(left));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {
      timedOut = true;
      break;
    }
    if (ready < 0) break;
    char buffer[512];
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    text.append(buffer, std::size_t(n));
  }
  ::close(fds[0]);
  int status = 0;
  if (timedOut) {
    ::kill(-child, SIGKILL);
    reap(child, status);
    return {std::nullopt, "no answer within " + std::to_string(timeoutSeconds) + " s; the probe was killed", true};
  }
  reap(child, status);

  std::vector<std::string> lines;
  for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  if (lines.size() == 5 && lines[0] == "ok") return {DeviceInfo{lines[1], lines[2], lines[3], lines[4], ""}, ""};
  if (lines.size() == 2 && lines[0] == "error") return {std::nullopt, lines[1]};
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    return {std::nullopt, "the probe could not start (/proc/self/exe probe-driver)"};
  return {std::nullopt, "the probe crashed (" + describeStatus(status) + ")"};
}

}  // namespace backends::gl
