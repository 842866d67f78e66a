#include "backends/gl/probe_in_child.h"

#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace backends::gl {
namespace {

// The child writes "ok\n" and the four strings, or "error\n" and the reason,
// one per line; none of them holds a newline.
void writeAll(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0) return;
    done += std::size_t(n);
  }
}

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n') c = ' ';
  return s;
}

}  // namespace

ProbeResult probeInChild(const std::function<DeviceInfo()>& probe) {
  int fds[2];
  if (::pipe(fds) != 0) return {std::nullopt, "cannot create a pipe for the probe"};
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return {std::nullopt, "cannot fork the probe"};
  }
  if (child == 0) {
    ::close(fds[0]);
    std::string text;
    try {
      const DeviceInfo d = probe();
      text = "ok\n" + oneLine(d.name) + "\n" + oneLine(d.driver) + "\n" + oneLine(d.driverVersion) + "\n" +
             oneLine(d.apiVersion) + "\n";
    } catch (const std::exception& e) {
      text = "error\n" + oneLine(e.what()) + "\n";
    }
    writeAll(fds[1], text);
    ::_exit(0);  // no atexit handlers or destructors of the parent's state
  }
  ::close(fds[1]);
  std::string text;
  char buffer[512];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) text.append(buffer, std::size_t(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);

  std::vector<std::string> lines;
  for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  if (lines.size() == 5 && lines[0] == "ok") return {DeviceInfo{lines[1], lines[2], lines[3], lines[4], ""}, ""};
  if (lines.size() == 2 && lines[0] == "error") return {std::nullopt, lines[1]};
  return {std::nullopt, "the probe crashed (status " + std::to_string(status) + ")"};
}

}  // namespace backends::gl
